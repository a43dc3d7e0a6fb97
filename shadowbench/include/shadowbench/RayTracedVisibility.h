#pragma once

#include <engine/FrameContext.h>
#include <engine/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <span>

namespace shadowbench {

/// @brief Exact light visibility by ray casting the scene's triangles with Embree 3: the ground truth shadow
/// maps are measured against.
class RayTracedVisibility {
public:
    /// @brief Builds a BVH over every mesh of `scene` in world space. Throws engine::Error if Embree fails.
    explicit RayTracedVisibility(const engine::Scene& scene);
    ~RayTracedVisibility();
    RayTracedVisibility(const RayTracedVisibility&) = delete;
    RayTracedVisibility& operator=(const RayTracedVisibility&) = delete;

    /// @brief Hard visibility of a sun, spot or point light: 1 where the segment from the surface to the
    /// light (for a sun: the ray towards it) is free, 0 where it is blocked. Pixels with `covered[i] == 0`
    /// get 0. The ray starts a small offset off the surface, so a surface never shadows itself by rounding:
    /// 1e-4 of the scene size, or, once setViewer names where the pixels are seen from, 1e-4 of the distance
    /// from it (a tenth of a pixel's footprint or less), so the offset does not shorten shadows near the
    /// camera in a kilometre-wide scene; never below 1e-5 of the point's largest coordinate (float's
    /// resolution there, with margin). The offset follows `normals[i]`, or, once setViewer is called, the
    /// geometric normal of the triangle seen at the point, on the viewer's side: a shading normal may point
    /// through its own triangle (real models' smoothed normals do, up to 45° off), and an offset along it
    /// starts the ray behind the surface, which then shadows itself.
    void hardVisibility(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                        std::span<const std::uint8_t> covered, const engine::FrameLight& light,
                        std::span<float> visibility) const;

    /// @brief Soft visibility of an area light: the fraction of `samplesPerAxis`² rays, stratified and
    /// uniform in solid angle over the cone the light fills seen from the point, that reach it. A sun is a
    /// cone of half-angle `radius` (its angular radius, radians); a spot or point light a sphere of `radius`
    /// (world units), each ray ending at its near surface; a point inside the sphere is lit. A radius of 0
    /// is hardVisibility.
    void softVisibility(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                        std::span<const std::uint8_t> covered, const engine::FrameLight& light, float radius,
                        int samplesPerAxis, std::span<float> visibility) const;

    /// @brief The radius softVisibility takes for `light`'s own size: half its angular diameter for a sun,
    /// its radius for a spot or point light.
    [[nodiscard]] static float ownRadius(const engine::FrameLight& light);

    /// @brief Whether the edge of the shadow lies near each point with `reach[i] > 0`, across the light's
    /// rays: 1 where one of 16 points, `reach[i]` or half of it from the point (offset off the surface as in
    /// hardVisibility) in 8 directions perpendicular to its ray to the light, sees the light otherwise than
    /// `lit[i]` says the point does. A point so marked lies within `reach[i]` of its shadow's edge in the
    /// light's view, even where the other side is hidden from the camera: a shadowed one also under a caster
    /// narrower than that (a thin fin, the foot of a thin wall). From a lit point only the points it reaches
    /// by a free segment count: the others lie under its own surface, which shadows them, or inside a solid
    /// it meets in a concave crease, where no shadow of this receiver's has an edge.
    void edgeWithin(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                    std::span<const float> reach, std::span<const std::uint8_t> lit,
                    const engine::FrameLight& light, std::span<std::uint8_t> marked) const;
    /// @brief Sizes the ray offsets by the distance from `eye` (see hardVisibility).
    void setViewer(const glm::vec3& eye) { viewer_ = eye; }

    /// @brief Diagonal of the scene's bounding box (world units).
    [[nodiscard]] float sceneSize() const { return sceneSize_; }

    /// @brief The geometric normal of the triangle seen at `position`, on the viewer's side, once setViewer
    /// names where the pixels are seen from; `normal` before, or where no triangle lies there.
    [[nodiscard]] glm::vec3 facetNormal(const glm::vec3& position, const glm::vec3& normal) const;

private:
    /// How far a shadow ray from `position` starts off the surface (see hardVisibility).
    [[nodiscard]] float rayOffset(const glm::vec3& position) const;
    /// Where a shadow ray from `position` starts: that offset along the facet's normal.
    [[nodiscard]] glm::vec3 rayOrigin(const glm::vec3& position, const glm::vec3& normal) const;

    /// Casts one ray per entry of `directions`/`lengths` from `origins`, writing 1 for free and 0 for
    /// blocked.
    void castShadowRays(std::span<const glm::vec3> origins, std::span<const glm::vec3> directions,
                        std::span<const float> lengths, std::span<float> free) const;

    void* device_ = nullptr;
    void* scene_ = nullptr;
    float sceneSize_ = 1.0f;
    std::optional<glm::vec3> viewer_;
};

} // namespace shadowbench
