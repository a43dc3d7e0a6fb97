#pragma once

#include <engine/FrameContext.h>
#include <engine/Module.h>
#include <engine/ProgramCache.h>
#include <engine/gl/Buffer.h>
#include <engine/gl/VertexArray.h>

#include <functional>
#include <map>
#include <memory>
#include <span>

namespace engine {

/// @brief Counts of the last lighting pass.
struct FrameStats {
    std::size_t drawCalls = 0;
    std::size_t triangles = 0;
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
/// Keeps GPU copies of meshes (uploaded on first draw) and a per-frame uniform block with the camera and
/// up to kMaxLights lights.
class ForwardRenderer {
public:
    static constexpr int kMaxLights = 8;
    static constexpr GLuint kFrameBlockBinding = 0;

    ForwardRenderer(ShaderVariantLayout& layout, ProgramCache& programs);

    /// @brief Computes camera matrices and the light list, uploads the frame uniform block.
    /// Throws Error when `camera` has no camera component.
    FrameContext beginFrame(const Scene& scene, EntityId camera, const FrameTarget& target,
                            std::uint64_t frameIndex);

    /// @brief Draws every mesh of `scene` with the currently bound program (see ModuleHost::drawMeshes).
    void drawMeshes(const Scene& scene, const std::function<bool(EntityId, const glm::mat4&)>& beforeDraw);

    /// @brief Clears `frame.target` and draws every mesh lit, letting `modules` choose variants and bind
    /// their resources per draw.
    FrameStats lightingPass(const FrameContext& frame, std::span<Module* const> modules);

    LightingEnvironment environment;
    /// Output of the lighting pass. Default Shaded.
    OutputMode output = OutputMode::Shaded;

private:
    struct GpuMesh {
        gl::Buffer vertices;
        gl::Buffer indices;
        gl::VertexArray vertexArray;
        GLsizei indexCount = 0;
        bool hasNormals = false;
    };
    const GpuMesh& upload(const std::shared_ptr<const MeshData>& mesh);

    ProgramCache& programs_;
    ShaderVariantKey flatNormalsFlag_;
    ShaderVariantKey spotLightsFlag_;
    ShaderVariantKey worldPositionFlag_;
    ShaderVariantKey worldNormalFlag_;
    gl::Buffer frameBlock_;
    bool sceneHasSpotLights_ = false;
    // Keyed by the mesh pointer; the shared_ptr keeps the key alive as long as its GPU copy.
    std::map<const MeshData*, std::pair<std::shared_ptr<const MeshData>, GpuMesh>> meshes_;
};

} // namespace engine
