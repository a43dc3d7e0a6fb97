#pragma once

#include <engine/Bounds.h>
#include <engine/FrameContext.h>
#include <engine/MeshChunks.h>
#include <engine/Module.h>
#include <engine/ProgramCache.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/Framebuffer.h>
#include <engine/gl/Texture.h>
#include <engine/gl/VertexArray.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <utility>

namespace engine {

/// @brief Counts of the last lighting pass.
struct FrameStats {
    /// Chunks drawn (one draw call each) and their triangles; with a depth pre-pass, each is drawn twice but
    /// counted once.
    std::size_t drawCalls = 0;
    std::size_t triangles = 0;
    /// Chunks left out because their bounds lie outside the camera's view volume.
    std::size_t culledChunks = 0;
    /// Flat chunks a shadow pass left out because they shadow nothing (MeshPass::castersFor); 0 for the
    /// lighting pass.
    std::size_t shadowlessChunks = 0;
    /// Whether the lighting pass shaded against the view depth a module asked for this frame
    /// (ForwardRenderer::viewDepth), copied into the target, instead of drawing depth itself.
    bool sharedViewDepth = false;
    /// Milliseconds of the modules' pre-passes (e.g. shadow maps) and of the lighting pass; negative unless
    /// Engine::setPassTiming enabled timing (the method is Engine::passTiming()).
    double prePassMilliseconds = -1.0;
    double lightingMilliseconds = -1.0;
};

/// @brief What the lighting pass writes: the shaded colour, or surface data for measurements (use a float
/// RenderTarget for those).
enum class OutputMode { Shaded, WorldPosition, WorldNormal };

/// @brief Scene-wide lighting environment.
struct LightingEnvironment {
    /// Linear ambient colour multiplied by each surface's base colour. Default 0.08 grey.
    glm::vec3 ambient{0.08f};
    /// Linear clear colour of the frame. Default near-black blue.
    glm::vec3 background{0.02f, 0.02f, 0.03f};
};

/// @brief Forward Blinn-Phong renderer: one lighting pass, every light evaluated per fragment.
///
/// Keeps GPU copies of meshes (uploaded on first draw, split into chunks of bounded size whose bounds are
/// computed once) and a per-frame uniform block with the camera and up to kMaxLights lights. Chunks outside
/// the view volume of a pass are not drawn.
class ForwardRenderer {
public:
    static constexpr int kMaxLights = 8;
    static constexpr GLuint kFrameBlockBinding = 0;

    ForwardRenderer(ShaderVariantLayout& layout, ProgramCache& programs);

    /// @brief Computes camera matrices and the light list, uploads the frame uniform block.
    /// Throws Error when `camera` has no camera component.
    FrameContext beginFrame(const Scene& scene, EntityId camera, const FrameTarget& target,
                            std::uint64_t frameIndex);

    /// @brief Draws the chunks of every mesh of `scene` that intersect the clip volume of
    /// `cullViewProjection` with the currently bound program (see ModuleHost::drawMeshes).
    /// @return Chunks drawn and culled, triangles drawn.
    FrameStats drawMeshes(const Scene& scene, const glm::mat4& cullViewProjection, const MeshPass& pass,
                          const std::function<bool(EntityId, const glm::mat4&)>& beforeDraw);

    /// @brief Calls `visit(entity, model, localBounds)` for every entity with a non-empty mesh; the bounds of
    /// each mesh are computed once.
    void forEachMeshBounds(const Scene& scene,
                           const std::function<void(EntityId, const glm::mat4&, const Aabb&)>& visit);

    /// @brief Clears `frame.target` and draws every mesh lit, letting `modules` choose variants and bind
    /// their resources per draw. Where a module asked for the frame's viewDepth, the lighting pass copies
    /// that depth into the target and shades with an EQUAL test, as after its own depth pre-pass.
    FrameStats lightingPass(const FrameContext& frame, std::span<Module* const> modules);

    /// @brief The depth of `frame`'s view as the lighting pass sees it (ModuleHost::viewDepth): on the first
    /// call of a frame, draws the lighting pass's depth pre-pass into a texture of the target's size and
    /// depth format, which the lighting pass then copies in instead of drawing depth again. Returns that
    /// texture, or 0 with nothing drawn when shareViewDepth is off or the target's depth buffer cannot take
    /// an exact copy (none, multisampled, or a format no texture matches or llvmpipe does not copy exactly).
    /// Leaves the target and its viewport bound.
    GLuint viewDepth(const FrameContext& frame);

    /// @brief GPU bytes of the vertex and index buffers of the meshes held (uploaded and still referenced).
    [[nodiscard]] std::size_t meshBytes() const;
    /// @brief Meshes held: those drawn or bounded so far that a scene still references.
    [[nodiscard]] std::size_t cachedMeshCount() const { return meshes_.size(); }
    /// @brief Frees the GPU copy and bounds of every mesh no scene references any more (its scenes were
    /// dropped). The cache holds meshes weakly, so several renderers drawing one scene (the sandbox's two
    /// sides) each let go. beginFrame calls it, so long sessions that switch scenes do not accumulate meshes.
    void releaseUnreferencedMeshes();

    LightingEnvironment environment;
    /// Output of the lighting pass. Default Shaded.
    OutputMode output = OutputMode::Shaded;
    /// Size of the chunks meshes are split into; applies to meshes uploaded afterwards. Default
    /// ChunkLimits{}.
    ChunkLimits chunkLimits;
    /// Leave out chunks outside each pass's view volume (exact: a culled chunk has no fragment). Default
    /// true.
    bool culling = true;
    /// Lay down depth first, then shade with an EQUAL depth test, so expensive lighting (shadow filtering)
    /// runs once per visible pixel. Pays when overdraw is high and lighting costs more than a second
    /// geometry pass (docs/RESULTS.md). Default false.
    bool depthPrePass = false;
    /// Hand modules that ask for the view's depth (viewDepth) the lighting pass's own depth pre-pass, so the
    /// view is drawn in depth once a frame and shaded once per pixel. Default true; false makes them draw
    /// their own, to compare.
    bool shareViewDepth = true;
    /// What the lighting pass does with the faces of closed parts that their other faces hide from the camera
    /// (HiddenFaces). Default Skip: the same image at about half a closed mesh's triangles.
    HiddenFaces lightingHiddenFaces = HiddenFaces::Skip;
    /// Encode the lighting pass's linear colour where the target stores sRGB (GL_FRAMEBUFFER_SRGB), as a
    /// display expects it. Default true; false stores the linear values as they are, as fixed-function OpenGL
    /// (the osgShadow peer) does, darker in the mid-tones: what the encode costs, to compare.
    bool encodeSrgb = true;
    /// Leave out of a shadow pass the flat chunks that shadow nothing, where the pass asks
    /// (MeshPass::castersFor). Default true; false draws them, to compare.
    bool leaveOutShadowlessChunks = true;

private:
    struct GpuMesh {
        gl::Buffer vertices;
        gl::Buffer indices;
        gl::VertexArray vertexArray;
        std::vector<MeshChunk> chunks;
    };
    struct CachedMesh {
        /// Weak: the scenes own meshes; the cache only notices when they are gone.
        std::weak_ptr<const MeshData> mesh;
        Aabb bounds;
        std::optional<GpuMesh> gpu;
    };
    CachedMesh& cached(const std::shared_ptr<const MeshData>& mesh);
    const GpuMesh& upload(CachedMesh& entry, const MeshData& mesh);
    /// The flat chunks of `scene`'s meshes that shadow nothing from `light`, in address order.
    std::vector<const MeshChunk*> shadowlessChunks(const Scene& scene, const glm::vec4& light);
    /// Draws every mesh's depth with the depth pre-pass program, as the lighting pass would place it.
    void drawDepth(const FrameContext& frame);
    void drawLit(const FrameContext& frame, std::span<Module* const> modules, FrameStats& stats);
    /// Copies viewDepth's depth into `target` within its scissor box, if the scissor test is on.
    void copyViewDepth(const FrameTarget& target) const;
    /// Whether viewDepth drew `frame`'s depth and the lighting pass has not used it yet.
    [[nodiscard]] bool holdsViewDepthOf(const FrameContext& frame) const;

    ProgramCache& programs_;
    ShaderVariantKey flatNormalsFlag_;
    ShaderVariantKey positionalLightsFlag_; // GS_HAS_POSITIONAL_LIGHTS: the frame has spot or point lights
    ShaderVariantKey worldPositionFlag_;
    ShaderVariantKey worldNormalFlag_;
    ShaderVariantKey lightCountBits_ = 0; // the frame's light count in the GS_LIGHT_COUNT_BIT flags
    std::array<ShaderVariantKey, 4> lightCountFlags_{};
    gl::Buffer frameBlock_;
    // viewDepth's texture and framebuffer, and the frame (index and target) whose depth they hold until the
    // lighting pass copies it.
    std::optional<gl::Texture> viewDepthTexture_;
    std::optional<gl::Framebuffer> viewDepthFramebuffer_;
    std::optional<std::pair<std::uint64_t, FrameTarget>> viewDepthFrame_;
    bool sceneHasPositionalLights_ = false;
    // Keyed by the mesh pointer; an entry whose mesh died is released (or replaced when its address is
    // reused).
    std::map<const MeshData*, CachedMesh> meshes_;
};

} // namespace engine
