#pragma once

#include <engine/Bounds.h>
#include <engine/FrameContext.h>
#include <engine/ShaderLibrary.h>
#include <engine/ShaderVariantKey.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

class ProgramCache;
namespace gl {
class Program;
}

/// @brief Bumped whenever Module, ModuleHost, FrameContext or DrawContext change layout or meaning.
inline constexpr std::uint32_t kModuleAbiVersion = 6;

/// @brief Identifies the compiler and C++ library ABI; a module built with another one is refused,
/// because C++ classes cross the module boundary.
#define GS_MODULE_BUILD_TAG                                                                                  \
    "gcc-abi-" GS_STRINGIFY(__GXX_ABI_VERSION) "-cxx11abi-" GS_STRINGIFY(_GLIBCXX_USE_CXX11_ABI)
#define GS_STRINGIFY_IMPL(x) #x
#define GS_STRINGIFY(x) GS_STRINGIFY_IMPL(x)

/// @brief Whether a pass draws the faces of closed parts that their other faces hide from its viewpoint
/// (hiddenFace): leaving them out stores the same nearest depth, at about half a closed mesh's triangles.
enum class HiddenFaces { Draw, Skip };

/// @brief What a pass through ModuleHost::drawMeshes may leave out.
struct MeshPass {
    HiddenFaces hiddenFaces = HiddenFaces::Draw;
    /// For a shadow pass that stores only depths compared against receivers: the light's homogeneous position
    /// (w = 0: the direction towards a directional light). Flat chunks with no mesh of the scene behind them
    /// as the light sees them shadow nothing, and are left out (chunksCastingNoShadow).
    std::optional<glm::vec4> castersFor;
};

/// @brief What one ModuleHost::drawMeshes call drew and left out.
struct DrawnMeshes {
    /// Chunks drawn (one draw call each) and their triangles.
    std::size_t drawCalls = 0;
    std::size_t triangles = 0;
    /// Chunks outside the pass's clip volume.
    std::size_t culledChunks = 0;
    /// Flat chunks left out because they shadow nothing (MeshPass::castersFor).
    std::size_t shadowlessChunks = 0;
};

/// @brief Services the engine offers to attached modules.
class ModuleHost {
public:
    virtual ~ModuleHost() = default;
    /// @brief Where modules register their GLSL files (names should start with the module's folder).
    virtual ShaderLibrary& shaders() = 0;
    /// @brief The lazy program cache; modules compile their own pass programs through it.
    virtual ProgramCache& programs() = 0;
    /// @brief The variant bit for `defineName` (registered on first use).
    virtual ShaderVariantKey variantFlag(std::string_view defineName) = 0;
    /// @brief Reserves a texture unit no other module or the engine uses.
    virtual GLuint reserveTextureUnit() = 0;
    /// @brief Draws the chunks of every mesh of `scene` that intersect the clip volume of
    /// `cullViewProjection` (the pass's own view-projection: culling is then exact); `beforeDraw(entity,
    /// model)` runs once per mesh with a visible chunk, sets per-draw state and may return false to skip that
    /// mesh. Used by pre-passes (e.g. shadow maps) with their own program. With HiddenFaces::Skip the host
    /// sets the cull-face state per chunk and leaves culling disabled; with Draw it leaves that state alone.
    virtual DrawnMeshes
    drawMeshes(const Scene& scene, const glm::mat4& cullViewProjection, const MeshPass& pass,
               const std::function<bool(EntityId, const glm::mat4& model)>& beforeDraw) = 0;
    /// @brief The depth of `frame`'s view as its lighting pass will see it, for pre-passes that measure what
    /// the camera sees (e.g. shadow maps fitted to the visible samples): a depth texture of the target's
    /// size (window depths, rows from the bottom), drawn on the frame's first call by the lighting pass's own
    /// depth pre-pass, which the lighting pass then reuses, so the view is drawn in depth once a frame. 0
    /// when the target cannot take it (ForwardRenderer::viewDepth): the caller then draws its own. Leaves
    /// the frame's framebuffer and viewport bound.
    virtual GLuint viewDepth(const FrameContext& frame) = 0;
    /// @brief Calls `visit(entity, model, localBounds)` for every entity with a mesh; each mesh's bounds are
    /// computed once, so per-frame fits (e.g. a light's frustum) need not walk vertices.
    virtual void forEachMeshBounds(
        const Scene& scene,
        const std::function<void(EntityId, const glm::mat4& model, const Aabb& localBounds)>& visit) = 0;
    /// @brief Returns and forgets the GL errors recorded since the engine last checked (GlDebug::takeErrors),
    /// for a module that answers one it caused: e.g. the GL_OUT_OF_MEMORY of an allocation the driver
    /// refused, which it retries smaller. Through the host, as a module loaded from a library has its own
    /// copy of the engine's statics.
    virtual std::vector<std::string> takeGlErrors() = 0;
};

/// @brief A plugin that extends the renderer. The engine calls the hooks in this fixed order:
///
/// 1. `attach` once, then `shaderChunks` (chunks are injected into every program compiled afterwards);
/// 2. per frame, for every module in attach order: `prepareFrame`, then `renderPrePasses`;
/// 3. the lighting pass: per draw, `variantBits` of every module pick the program variant, then
///    `bindLightingResources` of every module runs with that program in use;
/// 4. `debugDraw` of every module, with the frame's target bound;
/// 5. `detach` once before the module is destroyed.
class Module {
public:
    virtual ~Module() = default;
    [[nodiscard]] virtual std::string_view name() const = 0;

    virtual void attach(ModuleHost& /*host*/) {}
    virtual void detach() {}
    [[nodiscard]] virtual std::vector<ShaderChunk> shaderChunks() const { return {}; }
    virtual void prepareFrame(const FrameContext& /*frame*/) {}
    virtual void renderPrePasses(const FrameContext& /*frame*/) {}
    [[nodiscard]] virtual ShaderVariantKey variantBits(const DrawContext& /*draw*/) const { return 0; }
    virtual void bindLightingResources(const gl::Program& /*program*/, const DrawContext& /*draw*/) {}
    virtual void debugDraw(const FrameContext& /*frame*/) {}
};

/// @brief What a module shared library exports through `gsModuleDescriptor()`.
struct ModuleDescriptor {
    std::uint32_t abiVersion;
    const char* buildTag;
    const char* name;
    Module* (*create)();
    void (*destroy)(Module*);
};

} // namespace engine

/// @brief Exports `ModuleClass` from a module shared library under `moduleName`.
#define GS_EXPORT_MODULE(moduleName, ModuleClass)                                                            \
    extern "C" __attribute__((visibility("default"))) const engine::ModuleDescriptor* gsModuleDescriptor() { \
        static const engine::ModuleDescriptor descriptor{                                                    \
            engine::kModuleAbiVersion, GS_MODULE_BUILD_TAG, moduleName,                                      \
            []() -> engine::Module* { return new ModuleClass(); },                                           \
            [](engine::Module* module) { delete module; }};                                                  \
        return &descriptor;                                                                                  \
    }
