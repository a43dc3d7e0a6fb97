// Refinement + limit evaluation of a ~2k-quad cage, with memory per output vertex.
//
// OpenSubdiv's TopologyRefiner does not report its memory use, so the heap is measured instead: global
// operator new/delete are replaced to track live bytes, and the peak during evaluate() (refiner, primvar
// buffers and the output together) is reported next to a sizeof-based size of the output MeshData.
//
// With glibc's default settings about half of the time goes to page faults: the ~40 MB the refiner allocates
// is returned to the kernel after every call and faulted in again on the next. To time a warm heap instead,
// run with GLIBC_TUNABLES=glibc.malloc.trim_threshold=1000000000:glibc.malloc.mmap_threshold=1000000000

#include "content/CageShapes.h"
#include "content/SubdivisionSurface.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {

std::atomic<std::size_t> liveBytes{0};
std::atomic<std::size_t> peakBytes{0};

void recordAllocation(std::size_t bytes) {
    const std::size_t live = liveBytes.fetch_add(bytes) + bytes;
    std::size_t peak = peakBytes.load();
    while (live > peak && !peakBytes.compare_exchange_weak(peak, live)) {
    }
}

} // namespace

void* operator new(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    recordAllocation(malloc_usable_size(p));
    return p;
}

// GCC flags free() in a replacement operator delete as mismatched with operator new once it inlines one into
// the other, although both sides of this replacement pair use malloc/free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept {
    if (p != nullptr) {
        liveBytes.fetch_sub(malloc_usable_size(p));
        std::free(p);
    }
}

void operator delete(void* p, std::size_t) noexcept {
    operator delete(p);
}
#pragma GCC diagnostic pop

namespace {

std::size_t meshBytes(const engine::MeshData& mesh) {
    return mesh.positions.size() * sizeof(glm::vec3) + mesh.normals.size() * sizeof(glm::vec3) +
           mesh.indices.size() * sizeof(std::uint32_t) + sizeof(engine::MeshData);
}

// 64 x 32 = 2048 quads, refined to level 3 (131072 quads, 262144 triangles).
void BM_TorusRefineAndLimit(benchmark::State& state) {
    const int level = static_cast<int>(state.range(0));
    const content::SubdivisionSurface surface(content::CageShapes::torus(64, 32, 1.0f, 0.3f));
    std::size_t vertices = 0;
    std::size_t outputBytes = 0;
    std::size_t peak = 0;
    for (auto _ : state) {
        const std::size_t baseline = liveBytes.load();
        peakBytes.store(baseline);
        const content::SubdivisionSurface::Result result = surface.evaluate(level);
        benchmark::DoNotOptimize(result.mesh.positions.data());
        vertices = result.mesh.positions.size();
        outputBytes = meshBytes(result.mesh);
        peak = peakBytes.load() - baseline;
    }
    const auto perVertex = [vertices](std::size_t bytes) {
        return static_cast<double>(bytes) / static_cast<double>(vertices);
    };
    state.counters["cage_quads"] = static_cast<double>(surface.cage().faces.size());
    state.counters["out_vertices"] = static_cast<double>(vertices);
    state.counters["mesh_B/vertex"] = perVertex(outputBytes);
    state.counters["peak_heap_B/vertex"] = perVertex(peak);
}

BENCHMARK(BM_TorusRefineAndLimit)->Arg(3)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
