#include "VisibleSamples.h"

#include <engine/ProgramCache.h>
#include <engine/ShaderLibrary.h>

#include <glm/gtc/type_ptr.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <string>

namespace shadows {

namespace {

const engine::ProgramDesc kSampleDepthProgram{"shadows/depth.vert", "shadows/depth.frag"};
constexpr int kSliceWords = 7;
constexpr std::size_t kBoundsWords = 2 + kSampleSlices * kSliceWords;

/// The float an order-preserving word of samples.comp (gsOrderedBits) stands for.
float fromOrderedBits(std::uint32_t word) {
    const std::uint32_t bits = (word & 0x80000000u) != 0u ? word & 0x7fffffffu : ~word;
    return std::bit_cast<float>(bits);
}

/// The buffer's starting values: minima all ones (above every float), maxima and counts zero.
std::array<std::uint32_t, kBoundsWords> clearedBounds() {
    std::array<std::uint32_t, kBoundsWords> words{};
    words[0] = 0xffffffffu;
    for (int s = 0; s < kSampleSlices; ++s) {
        for (int axis = 0; axis < 3; ++axis) {
            words[2 + static_cast<std::size_t>(s * kSliceWords + axis)] = 0xffffffffu;
        }
    }
    return words;
}

} // namespace

const engine::gl::Program& VisibleSamples::reduction(engine::ModuleHost& host, bool depthRange) {
    std::unique_ptr<engine::gl::Program>& program = depthRange ? depthRangeProgram_ : lightRectsProgram_;
    if (!program) {
        const std::string pass = depthRange ? "GS_SAMPLES_DEPTH_RANGE" : "GS_SAMPLES_LIGHT_RECTS";
        const std::vector<std::string> defines{"#define " + pass};
        const std::array stages{
            host.shaders().preprocess(GL_COMPUTE_SHADER, "shadows/samples.comp", defines)};
        program = std::make_unique<engine::gl::Program>("shadows/samples.comp [" + pass + "]", stages);
    }
    return *program;
}

void VisibleSamples::draw(engine::ModuleHost& host, const engine::FrameContext& frame, const FitView& fit) {
    const glm::ivec2 size = glm::max(frame.target.size, glm::ivec2(1));
    if (!depth_ || size != size_) {
        size_ = size;
        depth_.emplace(GL_DEPTH_COMPONENT32F, size_);
        depth_->setFilter(GL_NEAREST, GL_NEAREST);
        framebuffer_.emplace("shadows: visible samples");
        framebuffer_->attach(GL_DEPTH_ATTACHMENT, *depth_);
        framebuffer_->setDrawBuffers({GL_NONE});
        framebuffer_->check();
    }

    // What the lighting pass will see: every mesh, both faces, depth only (the shadow pass's program without
    // a stored value).
    const glm::mat4 viewProjection = fit.projection * fit.view;
    const engine::gl::Program& program = host.programs().get(kSampleDepthProgram, 0);
    program.use();
    framebuffer_->bind();
    glViewport(0, 0, size_.x, size_.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    program.set("uLightViewProjection", viewProjection);
    host.drawMeshes(frame.scene, viewProjection, [&](engine::EntityId, const glm::mat4& model) {
        program.set("uModel", model);
        return true;
    });
    glBindFramebuffer(GL_FRAMEBUFFER, frame.target.framebuffer);
    glViewport(0, 0, frame.target.size.x, frame.target.size.y);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

std::optional<VisibleSamples::Bounds>
VisibleSamples::measure(engine::ModuleHost& host, const engine::FrameContext& frame, const FitView& fit,
                        const glm::mat4& worldToLight, float weight, float blend) {
    draw(host, frame, fit);
    if (!bounds_) {
        bounds_.emplace(kBoundsWords * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const glm::mat4 viewProjection = fit.projection * fit.view;

    // 8x8 invocations a group, each reducing a 16x16 block of texels (samples.comp's GS_BLOCK).
    constexpr int kGroupTexels = 8 * 16;
    const glm::ivec2 groups = (size_ + glm::ivec2(kGroupTexels - 1)) / kGroupTexels;
    const glm::mat4 clipToWorld = glm::inverse(viewProjection);
    std::array<std::uint32_t, kBoundsWords> words = clearedBounds();
    const auto run = [&](const engine::gl::Program& program) {
        bounds_->update(0, sizeof(words), words.data());
        program.use();
        program.set("uDepth", 0);
        program.set("uSize", size_);
        glBindTextureUnit(0, depth_->id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bounds_->id());
        glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glGetNamedBufferSubData(bounds_->id(), 0, sizeof(words), words.data());
    };

    const engine::gl::Program& depthRange = reduction(host, true);
    depthRange.use();
    depthRange.set("uClipToView", glm::inverse(fit.projection));
    run(depthRange);
    Bounds result;
    result.viewDepth = {fromOrderedBits(words[0]), fromOrderedBits(words[1])};
    if (words[1] == 0u || !std::isfinite(result.viewDepth.x) || !std::isfinite(result.viewDepth.y) ||
        !(result.viewDepth.x > 0.0f) || !(result.viewDepth.y >= result.viewDepth.x)) {
        return std::nullopt;
    }

    // The slices' bounds come from the CPU, so the GPU and its mirror assign every sample alike.
    result.sliceDepths = sampleSliceDepths(result.viewDepth, weight, blend);
    const engine::gl::Program& lightRects = reduction(host, false);
    lightRects.use();
    lightRects.set("uClipToWorld", clipToWorld);
    lightRects.set("uWorldToView", fit.view);
    lightRects.set("uWorldToLight", worldToLight);
    glUniform2fv(lightRects.uniformLocation("uSliceDepths"), kSampleSlices,
                 glm::value_ptr(result.sliceDepths.front()));
    words = clearedBounds();
    run(lightRects);
    for (int s = 0; s < kSampleSlices; ++s) {
        const std::size_t base = 2 + static_cast<std::size_t>(s * kSliceWords);
        LightRect& rect = result.slices[static_cast<std::size_t>(s)];
        rect.samples = words[base + 6];
        if (rect.samples > 0) {
            rect.min = {fromOrderedBits(words[base]), fromOrderedBits(words[base + 1]),
                        fromOrderedBits(words[base + 2])};
            rect.max = {fromOrderedBits(words[base + 3]), fromOrderedBits(words[base + 4]),
                        fromOrderedBits(words[base + 5])};
        }
    }
    glUseProgram(0);
    return result;
}

std::vector<float> VisibleSamples::readDepth() const {
    std::vector<float> depth(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
    if (depth_) {
        glGetTextureImage(depth_->id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                          static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    }
    return depth;
}

} // namespace shadows
