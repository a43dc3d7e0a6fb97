#pragma once

// Renders a scene with the shadow module into float targets and hands back, per pixel, the surface position,
// normal and the first shadowed light's visibility, so tests can compare against analytic ground truth.
#include "../engine/GLTestContext.h"

#include <engine/Engine.h>
#include <engine/RenderTarget.h>
#include <shadows/ShadowModule.h>

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

struct ShadowMeasurement {
    glm::ivec2 size{0};
    std::vector<glm::vec4> position; // w = 1 where a surface covers the pixel
    std::vector<glm::vec3> normal;
    std::vector<float> visibility;
    float texelWorldSize = 0.0f;                       // of light 0's map (orthographic maps)
    std::vector<shadows::LightProjection> projections; // every map of light 0 (cascades near to far, faces)

    static ShadowMeasurement render(const engine::Scene& scene, engine::EntityId camera,
                                    const shadows::ShadowSettings& settings, glm::ivec2 size) {
        glTestContext();
        ShadowMeasurement m;
        m.size = size;
        engine::Engine engine;
        auto* module = static_cast<shadows::ShadowModule*>(
            &engine.addModule(std::make_unique<shadows::ShadowModule>(settings)));
        engine::RenderTarget target(size, engine::ColorFormat::Rgba32F);
        engine.renderer().environment.background = glm::vec3(0.0f);

        engine.renderer().output = engine::OutputMode::WorldPosition;
        engine.renderFrame(scene, camera, target);
        const std::vector<float> positions = target.readPixelsFloat();
        engine.renderer().output = engine::OutputMode::WorldNormal;
        engine.renderFrame(scene, camera, target);
        const std::vector<float> normals = target.readPixelsFloat();
        engine.renderer().output = engine::OutputMode::Shaded;
        shadows::ShadowSettings visibilityOnly = settings;
        visibilityOnly.debugView = shadows::ShadowDebugView::Visibility;
        module->setSettings(visibilityOnly);
        engine.renderFrame(scene, camera, target);
        const std::vector<float> visibilities = target.readPixelsFloat();
        if (const auto projection = module->lightProjection(0)) {
            m.texelWorldSize = projection->texelScale;
        }
        m.projections = module->lightProjections(0);
        const std::size_t count = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
        for (std::size_t i = 0; i < count; ++i) {
            m.position.emplace_back(positions[4 * i], positions[4 * i + 1], positions[4 * i + 2],
                                    positions[4 * i + 3]);
            m.normal.emplace_back(normals[4 * i], normals[4 * i + 1], normals[4 * i + 2]);
            m.visibility.push_back(visibilities[4 * i]);
        }
        return m;
    }
};

/// Acne and leak rates of one measurement against a ground-truth classifier.
struct ShadowErrors {
    std::size_t litPixels = 0;
    std::size_t shadowedPixels = 0;
    std::size_t acne = 0;      // truly lit, visibility < 0.5
    std::size_t leak = 0;      // truly shadowed, visibility > 0.5
    double darkeningSum = 0.0; // sum of 1 - visibility over truly lit pixels

    [[nodiscard]] double acneRate() const {
        return litPixels ? static_cast<double>(acne) / static_cast<double>(litPixels) : 0.0;
    }
    /// Mean light lost over truly lit pixels (the reference's Fig. 4.2.3 darkening).
    [[nodiscard]] double darkening() const {
        return litPixels ? darkeningSum / static_cast<double>(litPixels) : 0.0;
    }
    [[nodiscard]] double leakRate() const {
        return shadowedPixels ? static_cast<double>(leak) / static_cast<double>(shadowedPixels) : 0.0;
    }

    /// Counts one receiver, truly `shadowed` or lit, rendered with `visibility`.
    void add(bool shadowed, float visibility) {
        if (shadowed) {
            ++shadowedPixels;
            leak += visibility > 0.5f;
        } else {
            ++litPixels;
            acne += visibility < 0.5f;
            darkeningSum += 1.0 - static_cast<double>(visibility);
        }
    }
};

/// Whether the truth `occluded(q)` at `p` agrees with the truth `band` away from it in four directions across
/// `toLight`: `p` lies away from the true shadow edges, where acne and leak are scored.
template <typename Occluded>
bool awayFromShadowEdges(const glm::vec3& p, const glm::vec3& toLight, float band, Occluded occluded) {
    const glm::vec3 tilted(0.0f, 1.0f, 0.3f);
    const glm::vec3 helper = glm::length(glm::cross(toLight, tilted)) > 0.1f ? tilted : glm::vec3(1, 0, 0);
    const glm::vec3 across1 = glm::normalize(glm::cross(toLight, helper));
    const glm::vec3 across2 = glm::cross(toLight, across1);
    const bool shadowed = occluded(p);
    for (const glm::vec3& offset : {across1, -across1, across2, -across2}) {
        if (occluded(p + band * offset) != shadowed) {
            return false;
        }
    }
    return true;
}
