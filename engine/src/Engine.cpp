#include <engine/Engine.h>
#include <engine/Error.h>
#include <engine/GlDebug.h>

#include <algorithm>
#include <span>

std::span<const engine::EmbeddedShaderFile> gsEngineShaders();

namespace engine {

/// One attached module: either owned directly or through the shared library that made it.
struct Engine::Attached {
    std::unique_ptr<Module> owned;
    std::unique_ptr<LoadedModule> loaded;
    [[nodiscard]] Module& module() const { return owned ? *owned : loaded->module(); }
};

Engine::Engine() : programs_(shaders_, variants_), renderer_(variants_, programs_) {
    shaders_.add(gsEngineShaders());
}

Engine::~Engine() {
    while (!attached_.empty()) {
        attached_.back()->module().detach();
        attached_.pop_back();
    }
}

Module& Engine::addModule(std::unique_ptr<Module> module) {
    if (!module) {
        throw ModuleError("addModule: no module given");
    }
    auto entry = std::make_unique<Attached>();
    entry->owned = std::move(module);
    return attach(std::move(entry));
}

Module& Engine::loadModule(std::string_view name) {
    auto entry = std::make_unique<Attached>();
    entry->loaded = loader_.load(name);
    return attach(std::move(entry));
}

Module& Engine::attach(std::unique_ptr<Attached> entry) {
    Module& added = entry->module();
    if (module(added.name())) {
        throw ModuleError("module '" + std::string(added.name()) + "' is already attached");
    }
    added.attach(*this);
    attached_.push_back(std::move(entry));
    rebuildChunks();
    return added;
}

bool Engine::removeModule(std::string_view name) {
    const auto found = std::find_if(attached_.begin(), attached_.end(),
                                    [&](const auto& entry) { return entry->module().name() == name; });
    if (found == attached_.end()) {
        return false;
    }
    (*found)->module().detach();
    attached_.erase(found);
    rebuildChunks();
    return true;
}

Module* Engine::module(std::string_view name) const {
    for (const auto& entry : attached_) {
        if (entry->module().name() == name) {
            return &entry->module();
        }
    }
    return nullptr;
}

std::vector<Module*> Engine::modules() const {
    std::vector<Module*> list;
    for (const auto& entry : attached_) {
        list.push_back(&entry->module());
    }
    return list;
}

void Engine::rebuildChunks() {
    std::vector<ShaderChunk> chunks;
    for (const auto& entry : attached_) {
        auto contributed = entry->module().shaderChunks();
        chunks.insert(chunks.end(), std::make_move_iterator(contributed.begin()),
                      std::make_move_iterator(contributed.end()));
    }
    programs_.setChunks(std::move(chunks));
}

GLuint Engine::reserveTextureUnit() {
    GLint units = 0;
    glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &units);
    if (nextTextureUnit_ >= static_cast<GLuint>(units)) {
        throw Error("reserveTextureUnit: all " + std::to_string(units) + " texture units are reserved");
    }
    return nextTextureUnit_++;
}

DrawnMeshes Engine::drawMeshes(const Scene& scene, const glm::mat4& cullViewProjection, const MeshPass& pass,
                               const std::function<bool(EntityId, const glm::mat4&)>& beforeDraw) {
    const FrameStats drawn = renderer_.drawMeshes(scene, cullViewProjection, pass, beforeDraw);
    return {drawn.drawCalls, drawn.triangles, drawn.culledChunks, drawn.shadowlessChunks};
}

void Engine::forEachMeshBounds(const Scene& scene,
                               const std::function<void(EntityId, const glm::mat4&, const Aabb&)>& visit) {
    renderer_.forEachMeshBounds(scene, visit);
}

void Engine::setPassTiming(std::optional<TimingMethod> method) {
    if (method) {
        timer_.emplace(*method);
    } else {
        timer_.reset();
    }
}

std::optional<TimingMethod> Engine::passTiming() const {
    return timer_ ? std::optional<TimingMethod>(timer_->method()) : std::nullopt;
}

FrameStats Engine::renderFrame(const Scene& scene, EntityId camera, const FrameTarget& target) {
    const FrameContext frame = renderer_.beginFrame(scene, camera, target, frameIndex_++);
    const std::vector<Module*> list = modules();
    for (Module* module : list) {
        module->prepareFrame(frame);
    }
    if (timer_) {
        timer_->begin();
    }
    for (Module* module : list) {
        module->renderPrePasses(frame);
    }
    const double prePass = timer_ ? timer_->end() : -1.0;
    GlDebug::check("pre-passes");
    if (timer_) {
        timer_->begin();
    }
    FrameStats stats = renderer_.lightingPass(frame, list);
    stats.lightingMilliseconds = timer_ ? timer_->end() : -1.0;
    stats.prePassMilliseconds = prePass;
    for (Module* module : list) {
        module->debugDraw(frame);
    }
    GlDebug::check("lighting pass");
    return stats;
}

FrameStats Engine::renderFrame(const Scene& scene, EntityId camera, const RenderTarget& target) {
    return renderFrame(scene, camera, FrameTarget{target.framebuffer().id(), target.size()});
}

} // namespace engine
