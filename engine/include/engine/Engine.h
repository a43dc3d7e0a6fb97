#pragma once

#include <engine/ForwardRenderer.h>
#include <engine/GlDebug.h>
#include <engine/Module.h>
#include <engine/ModuleLoader.h>
#include <engine/PassTimer.h>
#include <engine/ProgramCache.h>
#include <engine/RenderTarget.h>
#include <engine/ShaderLibrary.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace engine {

/// @brief The engine: shader library, program cache, forward renderer and the attached modules.
///
/// Needs a current OpenGL 4.5 core context (HeadlessContext or WindowContext) for its whole life.
class Engine final : private ModuleHost {
public:
    Engine();
    ~Engine() override;
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    /// @brief Attaches a directly linked module. Throws ModuleError if one of that name is attached.
    Module& addModule(std::unique_ptr<Module> module);
    /// @brief Loads module `name` from its shared library (see ModuleLoader) and attaches it.
    Module& loadModule(std::string_view name);
    /// @brief Detaches and destroys module `name`; returns false when none is attached.
    bool removeModule(std::string_view name);
    /// @brief The attached module called `name`, or nullptr.
    [[nodiscard]] Module* module(std::string_view name) const;
    /// @brief Attached modules in hook order.
    [[nodiscard]] std::vector<Module*> modules() const;

    /// @brief Draws one frame of `scene` seen from `camera` into `target` (hook order: see Module).
    FrameStats renderFrame(const Scene& scene, EntityId camera, const FrameTarget& target);
    FrameStats renderFrame(const Scene& scene, EntityId camera, const RenderTarget& target);

    /// @brief Times the pre-passes and the lighting pass of every frame with `method` (FrameStats fields), or
    /// stops timing with nullopt. Timing waits for the GPU between passes: leave it off when not measuring.
    void setPassTiming(std::optional<TimingMethod> method);
    [[nodiscard]] std::optional<TimingMethod> passTiming() const;

    [[nodiscard]] ShaderLibrary& shaders() override { return shaders_; }
    [[nodiscard]] ProgramCache& programs() override { return programs_; }
    [[nodiscard]] ShaderVariantLayout& variants() { return variants_; }
    [[nodiscard]] ModuleLoader& moduleLoader() { return loader_; }
    [[nodiscard]] ForwardRenderer& renderer() { return renderer_; }

private:
    struct Attached;

    ShaderVariantKey variantFlag(std::string_view defineName) override { return variants_.flag(defineName); }
    GLuint reserveTextureUnit() override;
    DrawnMeshes drawMeshes(const Scene& scene, const glm::mat4& cullViewProjection, const MeshPass& pass,
                           const std::function<bool(EntityId, const glm::mat4& model)>& beforeDraw) override;
    GLuint viewDepth(const FrameContext& frame) override { return renderer_.viewDepth(frame); }
    void
    forEachMeshBounds(const Scene& scene,
                      const std::function<void(EntityId, const glm::mat4&, const Aabb&)>& visit) override;
    std::vector<std::string> takeGlErrors() override { return GlDebug::takeErrors(); }

    Module& attach(std::unique_ptr<Attached> entry);
    void rebuildChunks();

    ShaderLibrary shaders_;
    ShaderVariantLayout variants_;
    ProgramCache programs_;
    ForwardRenderer renderer_;
    ModuleLoader loader_;
    std::vector<std::unique_ptr<Attached>> attached_;
    std::optional<PassTimer> timer_;
    GLuint nextTextureUnit_ = 0;
    std::uint64_t frameIndex_ = 0;
};

} // namespace engine
