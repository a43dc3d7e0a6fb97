// Which renderers count as CPU rasterisers, and the allocator thresholds raised for them (no GL context).
#include <engine/AddressSanitizer.h>
#include <engine/GlContext.h>

#include <gtest/gtest.h>

namespace {

TEST(IsSoftwareRendererName, KnowsMesasCpuRasterisers) {
    EXPECT_TRUE(engine::isSoftwareRendererName("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(engine::isSoftwareRendererName("softpipe"));
    EXPECT_TRUE(engine::isSoftwareRendererName("Mesa X11 swrast"));
    EXPECT_FALSE(engine::isSoftwareRendererName("NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(engine::isSoftwareRendererName("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7)"));
    EXPECT_FALSE(engine::isSoftwareRendererName(""));
}

TEST(RaiseAllocatorThresholds, TakesOnGlibcsAllocatorOnly) {
#if defined(GS_ADDRESS_SANITIZER)
    // AddressSanitizer's allocator stands in for glibc's and refuses mallopt: nothing is tuned, as it says.
    EXPECT_FALSE(engine::raiseAllocatorThresholds());
#else
    // Both values are within what glibc accepts on 64-bit, so both calls succeed (and may repeat).
    EXPECT_TRUE(engine::raiseAllocatorThresholds());
    EXPECT_TRUE(engine::raiseAllocatorThresholds());
#endif
}

} // namespace
