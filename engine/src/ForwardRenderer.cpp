#include <engine/Error.h>
#include <engine/ForwardRenderer.h>
#include <engine/ShadowlessChunks.h>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <functional>
#include <iostream>
#include <optional>

namespace engine {

namespace {

// std140 mirror of FrameBlock in shaders/frame.glsl.
struct alignas(16) LightBlock {
    glm::vec4 colorIntensity;
    glm::vec4 position;
    glm::vec4 direction;
    glm::vec4 spot;
};
struct alignas(16) FrameBlock {
    glm::mat4 viewProjection;
    glm::vec4 cameraPosition;
    glm::vec4 ambient;
    glm::ivec4 lightCount;
    LightBlock lights[ForwardRenderer::kMaxLights];
};
static_assert(sizeof(FrameBlock) == 64 + 16 * 3 + 64 * ForwardRenderer::kMaxLights);

const ProgramDesc kForwardProgram{"forward.vert", "forward.frag"};
const ProgramDesc kDepthOnlyProgram{"forward.vert", "depth_only.frag"};

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

/// The GS_LIGHT_* constant of shaders/frame.glsl that position.w carries for `type`.
float shaderLightType(LightType type) {
    switch (type) {
    case LightType::Directional:
        return 0.0f;
    case LightType::Spot:
        return 1.0f;
    case LightType::Point:
        return 2.0f;
    }
    throw Error("render: unknown light type " + std::to_string(static_cast<int>(type)));
}

/// The texture format whose depth a blit copies into `framebuffer`'s depth buffer: blits need the same
/// depth and stencil formats. 0 when that buffer cannot take an exact copy: none, multisampled, or a format
/// with no matching texture or whose copy is not exact.
GLenum copyableDepthFormat(GLuint framebuffer) {
    GLint sampleBuffers = 0;
    glGetNamedFramebufferParameteriv(framebuffer, GL_SAMPLE_BUFFERS, &sampleBuffers);
    const GLenum attachment = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    GLint type = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                               &type);
    if (sampleBuffers != 0 || type == GL_NONE) {
        return 0;
    }
    GLint depthBits = 0;
    GLint stencilBits = 0;
    GLint componentType = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                               &depthBits);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment,
                                               GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment,
                                               GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &componentType);
    const bool isFloat = componentType == GL_FLOAT;
    if (depthBits == 32 && isFloat) {
        return stencilBits == 8 ? GL_DEPTH32F_STENCIL8 : stencilBits == 0 ? GL_DEPTH_COMPONENT32F : 0;
    }
    if (isFloat || componentType != GL_UNSIGNED_NORMALIZED) {
        return 0;
    }
    // Not packed 24-bit depth with stencil (a window's usual buffer): llvmpipe copies its depth alone,
    // leaving the stencil, through a shader, and the depths it writes then fail the EQUAL test.
    if (depthBits == 24) {
        return stencilBits == 0 ? GL_DEPTH_COMPONENT24 : 0;
    }
    return depthBits == 16 && stencilBits == 0 ? GL_DEPTH_COMPONENT16 : 0;
}

} // namespace

ForwardRenderer::ForwardRenderer(ShaderVariantLayout& layout, ProgramCache& programs)
    : programs_(programs), flatNormalsFlag_(layout.flag("GS_FLAT_NORMALS")),
      positionalLightsFlag_(layout.flag("GS_HAS_POSITIONAL_LIGHTS")),
      worldPositionFlag_(layout.flag("GS_OUTPUT_WORLD_POSITION")),
      worldNormalFlag_(layout.flag("GS_OUTPUT_WORLD_NORMAL")),
      lightCountFlags_{layout.flag("GS_LIGHT_COUNT_BIT0"), layout.flag("GS_LIGHT_COUNT_BIT1"),
                       layout.flag("GS_LIGHT_COUNT_BIT2"), layout.flag("GS_LIGHT_COUNT_BIT3")},
      frameBlock_(sizeof(FrameBlock), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    static_assert(kMaxLights < 16, "the light count must fit the four GS_LIGHT_COUNT_BIT flags");
}

void ForwardRenderer::releaseUnreferencedMeshes() {
    std::erase_if(meshes_, [](const auto& entry) { return entry.second.mesh.expired(); });
}

FrameContext ForwardRenderer::beginFrame(const Scene& scene, EntityId camera, const FrameTarget& target,
                                         std::uint64_t frameIndex) {
    releaseUnreferencedMeshes();
    viewDepthFrame_.reset();
    const Entity& cameraEntity = scene.entity(camera);
    if (!cameraEntity.camera) {
        throw Error("render: entity '" + cameraEntity.name + "' has no camera component");
    }
    FrameContext frame(scene);
    frame.camera = camera;
    frame.target = target;
    frame.frameIndex = frameIndex;
    const glm::mat4 cameraWorld = scene.worldMatrix(camera);
    frame.view = glm::inverse(cameraWorld);
    const float aspect =
        target.size.y > 0 ? static_cast<float>(target.size.x) / static_cast<float>(target.size.y) : 1.0f;
    frame.projection = cameraEntity.camera->projectionMatrix(aspect);
    frame.viewProjection = frame.projection * frame.view;
    frame.cameraPosition = glm::vec3(cameraWorld[3]);

    FrameBlock block{};
    block.viewProjection = frame.viewProjection;
    block.cameraPosition = glm::vec4(frame.cameraPosition, 1.0f);
    block.ambient = glm::vec4(environment.ambient, 0.0f);
    sceneHasPositionalLights_ = false;
    std::size_t skipped = 0;
    scene.forEach([&](EntityId id, const Entity& entity) {
        if (!entity.light) {
            return;
        }
        if (frame.lights.size() == kMaxLights) {
            ++skipped;
            return;
        }
        const glm::mat4 world = scene.worldMatrix(id);
        FrameLight light;
        light.index = static_cast<int>(frame.lights.size());
        light.entity = id;
        light.light = *entity.light;
        light.position = glm::vec3(world[3]);
        light.direction = glm::normalize(-glm::vec3(world[2]));
        // Spot and point lights shine from a position: only then does the shader need their code.
        sceneHasPositionalLights_ = sceneHasPositionalLights_ || light.light.type != LightType::Directional;
        block.lights[light.index] = {
            glm::vec4(light.light.color, light.light.intensity),
            glm::vec4(light.position, shaderLightType(light.light.type)), glm::vec4(light.direction, 0.0f),
            glm::vec4(std::cos(light.light.innerConeAngle), std::cos(light.light.outerConeAngle),
                      light.light.range, 0.0f)};
        frame.lights.push_back(light);
    });
    if (skipped > 0) {
        std::cerr << "render: the scene has " << (frame.lights.size() + skipped) << " lights; only the first "
                  << kMaxLights << " are drawn\n";
    }
    block.lightCount = glm::ivec4(static_cast<int>(frame.lights.size()), 0, 0, 0);
    lightCountBits_ = 0;
    for (std::size_t bit = 0; bit < lightCountFlags_.size(); ++bit) {
        lightCountBits_ |= (frame.lights.size() >> bit) & 1u ? lightCountFlags_[bit] : 0;
    }
    frameBlock_.update(0, sizeof block, &block);
    return frame;
}

ForwardRenderer::CachedMesh& ForwardRenderer::cached(const std::shared_ptr<const MeshData>& mesh) {
    auto found = meshes_.find(mesh.get());
    // Same address, other owner: the cached mesh died and a new one took its place before a release.
    const bool sameMesh = found != meshes_.end() && !found->second.mesh.owner_before(mesh) &&
                          !mesh.owner_before(found->second.mesh);
    if (sameMesh) {
        return found->second;
    }
    CachedMesh entry{mesh, {}, std::nullopt};
    for (const glm::vec3& p : mesh->positions) {
        entry.bounds.extend(p);
    }
    if (found != meshes_.end()) {
        found->second = std::move(entry);
        return found->second;
    }
    return meshes_.emplace(mesh.get(), std::move(entry)).first->second;
}

const ForwardRenderer::GpuMesh& ForwardRenderer::upload(CachedMesh& entry, const MeshData& mesh) {
    if (entry.gpu) {
        return *entry.gpu;
    }
    const ChunkedMesh chunked = splitIntoChunks(mesh, chunkLimits);
    const bool hasNormals = mesh.normals.size() == mesh.positions.size();
    std::vector<Vertex> vertices(chunked.sourceVertex.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const std::uint32_t source = chunked.sourceVertex[i];
        vertices[i] = {mesh.positions[source], hasNormals ? mesh.normals[source] : glm::vec3(0.0f)};
    }
    entry.gpu.emplace(GpuMesh{gl::Buffer::fromSpan<Vertex>(vertices),
                              gl::Buffer::fromSpan<std::uint32_t>(chunked.indices),
                              {},
                              chunked.chunks});
    GpuMesh& gpu = *entry.gpu;
    gpu.vertexArray.setVertexBuffer(0, gpu.vertices, sizeof(Vertex));
    gpu.vertexArray.setFloatAttribute(0, 0, 3, offsetof(Vertex, position));
    gpu.vertexArray.setFloatAttribute(1, 0, 3, offsetof(Vertex, normal));
    gpu.vertexArray.setIndexBuffer(gpu.indices);
    return gpu;
}

std::size_t ForwardRenderer::meshBytes() const {
    std::size_t bytes = 0;
    for (const auto& [key, entry] : meshes_) {
        bytes += entry.gpu ? entry.gpu->vertices.size() + entry.gpu->indices.size() : 0;
    }
    return bytes;
}

void ForwardRenderer::forEachMeshBounds(
    const Scene& scene, const std::function<void(EntityId, const glm::mat4&, const Aabb&)>& visit) {
    scene.forEach([&](EntityId id, const Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh || entity.mesh->mesh->positions.empty()) {
            return;
        }
        visit(id, scene.worldMatrix(id), cached(entity.mesh->mesh).bounds);
    });
}

std::vector<const MeshChunk*> ForwardRenderer::shadowlessChunks(const Scene& scene, const glm::vec4& light) {
    std::vector<PlacedChunks> meshes;
    bool anyFlat = false;
    scene.forEach([&](EntityId id, const Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh || entity.mesh->mesh->indices.empty()) {
            return;
        }
        CachedMesh& entry = cached(entity.mesh->mesh);
        const GpuMesh& gpu = upload(entry, *entity.mesh->mesh);
        anyFlat = anyFlat || std::any_of(gpu.chunks.begin(), gpu.chunks.end(),
                                         [](const MeshChunk& chunk) { return chunk.plane.has_value(); });
        meshes.push_back({scene.worldMatrix(id), entry.bounds, gpu.chunks});
    });
    if (!anyFlat) {
        return {};
    }
    std::vector<const MeshChunk*> shadowless = chunksCastingNoShadow(meshes, light);
    std::sort(shadowless.begin(), shadowless.end(), std::less<>{});
    return shadowless;
}

FrameStats ForwardRenderer::drawMeshes(const Scene& scene, const glm::mat4& cullViewProjection,
                                       const MeshPass& pass,
                                       const std::function<bool(EntityId, const glm::mat4&)>& beforeDraw) {
    FrameStats stats;
    const std::vector<const MeshChunk*> shadowless = pass.castersFor && leaveOutShadowlessChunks
                                                         ? shadowlessChunks(scene, *pass.castersFor)
                                                         : std::vector<const MeshChunk*>{};
    std::vector<const MeshChunk*> visible;
    // The cull-face state set last (GL_NONE: disabled), once this pass has set it.
    std::optional<GLenum> culled;
    scene.forEach([&](EntityId id, const Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh || entity.mesh->mesh->indices.empty()) {
            return;
        }
        const glm::mat4 model = scene.worldMatrix(id);
        const GpuMesh& gpu = upload(cached(entity.mesh->mesh), *entity.mesh->mesh);
        const glm::mat4 clipFromModel = cullViewProjection * model;
        visible.clear();
        for (const MeshChunk& chunk : gpu.chunks) {
            if (std::binary_search(shadowless.begin(), shadowless.end(), &chunk, std::less<>{})) {
                ++stats.shadowlessChunks;
            } else if (!culling || intersectsClipVolume(chunk.bounds, clipFromModel)) {
                visible.push_back(&chunk);
            } else {
                ++stats.culledChunks;
            }
        }
        if (visible.empty() || !beforeDraw(id, model)) {
            return;
        }
        gpu.vertexArray.bind();
        for (const MeshChunk* chunk : visible) {
            if (pass.hiddenFaces == HiddenFaces::Skip) {
                const GLenum face = hiddenFace(chunk->closure, chunk->closedBounds, clipFromModel);
                if (culled != face) {
                    if (face == GL_NONE) {
                        glDisable(GL_CULL_FACE);
                    } else {
                        glEnable(GL_CULL_FACE);
                        glCullFace(face);
                    }
                    culled = face;
                }
            }
            // The range tells the driver which vertices the draw reads: only the chunk's own.
            glDrawRangeElements(
                GL_TRIANGLES, chunk->firstVertex, chunk->firstVertex + chunk->vertexCount - 1,
                static_cast<GLsizei>(chunk->indexCount), GL_UNSIGNED_INT,
                reinterpret_cast<const void*>(std::uintptr_t{chunk->firstIndex} * sizeof(std::uint32_t)));
            ++stats.drawCalls;
            stats.triangles += chunk->indexCount / 3;
        }
    });
    if (culled.value_or(GL_NONE) != GL_NONE) {
        glDisable(GL_CULL_FACE);
    }
    return stats;
}

void ForwardRenderer::drawDepth(const FrameContext& frame) {
    const gl::Program& program = programs_.get(kDepthOnlyProgram, 0);
    program.use();
    drawMeshes(frame.scene, frame.viewProjection, MeshPass{lightingHiddenFaces, std::nullopt},
               [&](EntityId, const glm::mat4& model) {
                   program.set("uModel", model);
                   return true;
               });
}

void ForwardRenderer::drawLit(const FrameContext& frame, std::span<Module* const> modules,
                              FrameStats& stats) {
    const ShaderVariantKey outputBits = output == OutputMode::WorldPosition ? worldPositionFlag_
                                        : output == OutputMode::WorldNormal ? worldNormalFlag_
                                                                            : 0;
    const ShaderVariantKey sceneBits =
        (sceneHasPositionalLights_ ? positionalLightsFlag_ : 0) | outputBits | lightCountBits_;
    const MeshPass pass{lightingHiddenFaces, std::nullopt};
    const FrameStats drawn =
        drawMeshes(frame.scene, frame.viewProjection, pass, [&](EntityId id, const glm::mat4& model) {
            const MeshData& mesh = *frame.scene.entity(id).mesh->mesh;
            const DrawContext draw{frame, id, mesh, model};
            ShaderVariantKey key = sceneBits;
            if (mesh.normals.size() != mesh.positions.size()) {
                key |= flatNormalsFlag_;
            }
            for (const Module* module : modules) {
                key |= module->variantBits(draw);
            }
            const gl::Program& program = programs_.get(kForwardProgram, key);
            program.use();
            program.set("uModel", model);
            program.set("uNormalMatrix", glm::mat3(glm::transpose(glm::inverse(model))));
            program.set("uBaseColor", mesh.material.baseColor);
            program.set("uSpecularColor", mesh.material.specularColor);
            program.set("uShininess", mesh.material.shininess);
            for (Module* module : modules) {
                module->bindLightingResources(program, draw);
            }
            return true;
        });
    stats.drawCalls += drawn.drawCalls;
    stats.triangles += drawn.triangles;
    stats.culledChunks += drawn.culledChunks;
}

bool ForwardRenderer::holdsViewDepthOf(const FrameContext& frame) const {
    return viewDepthFrame_ && viewDepthFrame_->first == frame.frameIndex &&
           viewDepthFrame_->second.framebuffer == frame.target.framebuffer &&
           viewDepthFrame_->second.size == frame.target.size;
}

GLuint ForwardRenderer::viewDepth(const FrameContext& frame) {
    if (holdsViewDepthOf(frame)) {
        return viewDepthTexture_->id();
    }
    const glm::ivec2 size = frame.target.size;
    if (!shareViewDepth || size.x <= 0 || size.y <= 0) {
        return 0;
    }
    const GLenum format = copyableDepthFormat(frame.target.framebuffer);
    if (format == 0) {
        return 0;
    }
    if (!viewDepthTexture_ || viewDepthTexture_->internalFormat() != format ||
        viewDepthTexture_->size() != size) {
        viewDepthTexture_.emplace(format, size);
        viewDepthTexture_->setFilter(GL_NEAREST, GL_NEAREST);
        viewDepthFramebuffer_.emplace("render: view depth", *viewDepthTexture_);
    }
    viewDepthFramebuffer_->beginDepthPass(size);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameBlock_.id());
    drawDepth(frame);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.target.framebuffer);
    glViewport(0, 0, size.x, size.y);
    viewDepthFrame_.emplace(frame.frameIndex, frame.target);
    return viewDepthTexture_->id();
}

void ForwardRenderer::copyViewDepth(const FrameTarget& target) const {
    // Only the rectangle the lighting pass may touch: a scissor box, if one is set (the sandbox's split view
    // draws each side with its own engine). The copy itself runs unscissored: llvmpipe blits a scissored
    // depth copy through a shader, whose depths then fail the EQUAL test, where an unscissored one copies
    // the texels.
    glm::ivec4 box{0, 0, target.size.x, target.size.y};
    const bool scissored = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    if (scissored) {
        glm::ivec4 scissor{0};
        glGetIntegerv(GL_SCISSOR_BOX, &scissor.x);
        const glm::ivec2 low = glm::clamp(glm::ivec2(scissor.x, scissor.y), glm::ivec2(0), target.size);
        const glm::ivec2 high =
            glm::clamp(glm::ivec2(scissor.x + scissor.z, scissor.y + scissor.w), low, target.size);
        box = {low, high};
        glDisable(GL_SCISSOR_TEST);
    }
    // The formats match (copyableDepthFormat), so the copy holds the very depths drawing them here would.
    glBlitNamedFramebuffer(viewDepthFramebuffer_->id(), target.framebuffer, box.x, box.y, box.z, box.w, box.x,
                           box.y, box.z, box.w, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    if (scissored) {
        glEnable(GL_SCISSOR_TEST);
    }
}

FrameStats ForwardRenderer::lightingPass(const FrameContext& frame, std::span<Module* const> modules) {
    glBindFramebuffer(GL_FRAMEBUFFER, frame.target.framebuffer);
    glViewport(0, 0, frame.target.size.x, frame.target.size.y);
    if (encodeSrgb) {
        glEnable(GL_FRAMEBUFFER_SRGB);
    } else {
        glDisable(GL_FRAMEBUFFER_SRGB);
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    if (output == OutputMode::Shaded) {
        glClearColor(environment.background.r, environment.background.g, environment.background.b, 1.0f);
    } else {
        glClearColor(0.0f, 0.0f, 0.0f, 0.0f); // alpha 1 marks the pixels a surface covers (forward.frag)
    }
    glClearDepth(1.0);
    FrameStats stats;
    stats.sharedViewDepth = holdsViewDepthOf(frame);
    viewDepthFrame_.reset();
    glClear(stats.sharedViewDepth ? GL_COLOR_BUFFER_BIT : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBlockBinding, frameBlock_.id());

    if (stats.sharedViewDepth) {
        copyViewDepth(frame.target);
    } else if (depthPrePass) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawDepth(frame);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    if (stats.sharedViewDepth || depthPrePass) {
        glDepthFunc(GL_EQUAL);
        glDepthMask(GL_FALSE);
    }
    drawLit(frame, modules, stats);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    return stats;
}

} // namespace engine
