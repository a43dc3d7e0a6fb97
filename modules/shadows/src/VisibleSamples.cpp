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

/// The float an order-preserving word of samples.comp (gsOrderedBits) stands for.
float fromOrderedBits(std::uint32_t word) {
    const std::uint32_t bits = (word & 0x80000000u) != 0u ? word & 0x7fffffffu : ~word;
    return std::bit_cast<float>(bits);
}

} // namespace

const engine::gl::Program& VisibleSamples::reduction(engine::ModuleHost& host, Reduction pass) {
    std::unique_ptr<engine::gl::Program>& program =
        pass == Reduction::Whole ? wholeProgram_ : cascadeSlicesProgram_;
    if (!program) {
        const std::string define =
            pass == Reduction::Whole ? "GS_SAMPLES_WHOLE" : "GS_SAMPLES_CASCADE_SLICES";
        const std::vector<std::string> defines{"#define " + define};
        const std::array stages{
            host.shaders().preprocess(GL_COMPUTE_SHADER, "shadows/samples.comp", defines)};
        program = std::make_unique<engine::gl::Program>("shadows/samples.comp [" + define + "]", stages);
    }
    return *program;
}

std::array<std::uint32_t, VisibleSamples::kBoundsWords>
VisibleSamples::reduce(const engine::gl::Program& program) {
    // Minima start at all ones (above every float), maxima and counts at zero.
    std::array<std::uint32_t, kBoundsWords> words{};
    words[0] = 0xffffffffu;
    for (int s = 0; s < kSampleSlices; ++s) {
        for (int axis = 0; axis < 3; ++axis) {
            words[2 + static_cast<std::size_t>(s * kSliceWords + axis)] = 0xffffffffu;
        }
    }
    if (!bounds_) {
        bounds_.emplace(kBoundsWords * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    bounds_->update(0, sizeof(words), words.data());
    program.use();
    program.set("uDepth", 0);
    program.set("uSize", size_);
    program.set("uTexelToLight", texelToLight_);
    glUniform4fv(program.uniformLocation("uTexelToViewDepth"), 1, glm::value_ptr(texelToViewDepth_));
    glBindTextureUnit(0, depthTexture());
    // The gathers read the texture's own nearest filtering, not a comparison sampler left on the unit.
    glBindSampler(0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bounds_->id());
    // A group of 8x8 invocations covers 128x128 texels, 16x16 each (samples.comp's GS_GROUP_SIDE, GS_BLOCK).
    constexpr int kGroupTexels = 8 * 16;
    const glm::ivec2 groups = (size_ + glm::ivec2(kGroupTexels - 1)) / kGroupTexels;
    glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(bounds_->id(), 0, sizeof(words), words.data());
    glUseProgram(0);
    return words;
}

void VisibleSamples::draw(engine::ModuleHost& host, const engine::FrameContext& frame, const FitView& fit) {
    ++draws_;
    // The camera's own view is the one the lighting pass draws: take its depth pre-pass, drawn once for both.
    sharedDepth_ = fit == FitView{frame.view, frame.projection} ? host.viewDepth(frame) : 0;
    if (sharedDepth_ != 0) {
        size_ = frame.target.size;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        return;
    }
    size_ = glm::max(frame.target.size, glm::ivec2(1));
    if (!depth_ || depth_->size() != size_) {
        depth_.emplace(GL_DEPTH_COMPONENT32F, size_);
        depth_->setFilter(GL_NEAREST, GL_NEAREST);
        framebuffer_.emplace("shadows: visible samples", *depth_);
    }

    // What the lighting pass will see: every mesh, both faces, depth only (the shadow pass's program without
    // a stored value).
    const glm::mat4 viewProjection = fit.projection * fit.view;
    const engine::gl::Program& program = host.programs().get(kSampleDepthProgram, 0);
    program.use();
    framebuffer_->beginDepthPass(size_);
    program.set("uLightViewProjection", viewProjection);
    // The faces closed parts hide from the camera are left out, as the lighting pass leaves them: the same
    // depth.
    host.drawMeshes(frame.scene, viewProjection, engine::MeshPass{engine::HiddenFaces::Skip, std::nullopt},
                    [&](engine::EntityId, const glm::mat4& model) {
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
    // Window texel (x, y, depth) to clip space, then to world and on to the light's view, in double so the
    // products lose nothing the float steps would. The light's view is affine: its last row keeps the world
    // point's w, which then divides the light-space and view-depth results alike.
    glm::dmat4 texelToClip(1.0);
    texelToClip[0][0] = 2.0 / size_.x;
    texelToClip[1][1] = 2.0 / size_.y;
    texelToClip[2][2] = 2.0;
    texelToClip[3] = glm::dvec4(1.0 / size_.x - 1.0, 1.0 / size_.y - 1.0, -1.0, 1.0);
    const glm::dmat4 texelToWorld =
        glm::inverse(glm::dmat4(fit.projection) * glm::dmat4(fit.view)) * texelToClip;
    const glm::dmat4 toLight = glm::dmat4(worldToLight) * texelToWorld;
    const glm::dmat4 toView = glm::dmat4(fit.view) * texelToWorld;
    texelToLight_ = glm::mat4(toLight);
    for (int column = 0; column < 4; ++column) {
        texelToViewDepth_[column] = static_cast<float>(-toView[column][2]);
    }

    const std::array<std::uint32_t, kBoundsWords> words = reduce(reduction(host, Reduction::Whole));
    Bounds result;
    result.viewDepth = {fromOrderedBits(words[0]), fromOrderedBits(words[1])};
    if (words[1] == 0u || !std::isfinite(result.viewDepth.x) || !std::isfinite(result.viewDepth.y) ||
        !(result.viewDepth.x > 0.0f) || !(result.viewDepth.y >= result.viewDepth.x)) {
        return std::nullopt;
    }
    // The slices' bounds come from the CPU, so the GPU and its mirror assign every sample alike.
    result.sliceDepths = sampleSliceDepths(result.viewDepth, weight, blend);
    readSlices(words, 0, 1, result);
    return result;
}

void VisibleSamples::measureCascadeSlices(engine::ModuleHost& host, Bounds& bounds) {
    const engine::gl::Program& program = reduction(host, Reduction::CascadeSlices);
    program.use();
    glUniform2fv(program.uniformLocation("uSliceDepths"), kSampleSlices,
                 glm::value_ptr(bounds.sliceDepths.front()));
    readSlices(reduce(program), 1, kSampleSlices, bounds);
    bounds.cascadeSlices = true;
}

void VisibleSamples::readSlices(const std::array<std::uint32_t, kBoundsWords>& words, int first, int end,
                                Bounds& bounds) {
    for (int s = first; s < end; ++s) {
        const std::size_t base = 2 + static_cast<std::size_t>(s * kSliceWords);
        LightRect& rect = bounds.slices[static_cast<std::size_t>(s)];
        rect = {};
        rect.samples = words[base + 6];
        if (rect.samples > 0) {
            rect.min = {fromOrderedBits(words[base]), fromOrderedBits(words[base + 1]),
                        fromOrderedBits(words[base + 2])};
            rect.max = {fromOrderedBits(words[base + 3]), fromOrderedBits(words[base + 4]),
                        fromOrderedBits(words[base + 5])};
        }
    }
}

std::vector<float> VisibleSamples::readDepth() const {
    std::vector<float> depth(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y));
    if (depthTexture() != 0) {
        glGetTextureImage(depthTexture(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                          static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    }
    return depth;
}

} // namespace shadows
