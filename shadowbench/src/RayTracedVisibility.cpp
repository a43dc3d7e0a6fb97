#include <shadowbench/RayTracedVisibility.h>

#include <engine/Error.h>

#include <embree3/rtcore.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace shadowbench {

namespace {

RTCDevice device(void* handle) {
    return static_cast<RTCDevice>(handle);
}
RTCScene scene(void* handle) {
    return static_cast<RTCScene>(handle);
}

/// Direction and length from `position` towards the light: a sun is infinitely far along its direction; spot
/// and point lights sit at their position (a spot's cone does not limit its shadow rays: outside it the
/// surface is dark anyway).
void towardsLight(const engine::FrameLight& light, const glm::vec3& position, glm::vec3& direction,
                  float& length) {
    if (light.light.type == engine::LightType::Directional) {
        direction = -light.direction;
        length = std::numeric_limits<float>::infinity();
        return;
    }
    const glm::vec3 offset = light.position - position;
    length = glm::length(offset);
    direction = length > 0.0f ? offset / length : -light.direction;
}

/// Any two unit vectors completing `axis` to an orthonormal basis.
void basisAround(const glm::vec3& axis, glm::vec3& u, glm::vec3& v) {
    u = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
    v = glm::cross(axis, u);
}

/// Shadow rays gathered for one batched cast, each remembering its pixel.
struct RayBatch {
    std::vector<glm::vec3> origins;
    std::vector<glm::vec3> directions;
    std::vector<float> lengths;
    std::vector<std::size_t> pixelOf;

    /// A ray `segment` long (infinite towards a sun) stops just short of the light, which may sit on a
    /// surface.
    void add(const glm::vec3& origin, const glm::vec3& direction, float segment, std::size_t pixel) {
        origins.push_back(origin);
        directions.push_back(direction);
        lengths.push_back(std::isinf(segment) ? segment : segment * 0.9999f);
        pixelOf.push_back(pixel);
    }
};

} // namespace

RayTracedVisibility::RayTracedVisibility(const engine::Scene& source) {
    RTCDevice dev = rtcNewDevice(nullptr);
    if (!dev) {
        throw engine::Error("ground truth: Embree could not create a device (error " +
                            std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
    }
    device_ = dev;
    RTCScene sc = rtcNewScene(dev);
    scene_ = sc;
    rtcSetSceneBuildQuality(sc, RTC_BUILD_QUALITY_HIGH);
    // Watertight intersection: a ray through a shared edge or vertex hits one of its triangles (the lookup of
    // the facet under a pixel must not slip between two; shadow rays must not leak through seams).
    rtcSetSceneFlags(sc, RTC_SCENE_FLAG_ROBUST);
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(-std::numeric_limits<float>::max());
    source.forEach([&](engine::EntityId id, const engine::Entity& entity) {
        if (!entity.mesh || !entity.mesh->mesh || entity.mesh->mesh->indices.size() < 3) {
            return;
        }
        const engine::MeshData& mesh = *entity.mesh->mesh;
        const glm::mat4 world = source.worldMatrix(id);
        RTCGeometry geometry = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                     RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                     mesh.positions.size()));
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3 p = glm::vec3(world * glm::vec4(mesh.positions[i], 1.0f));
            low = glm::min(low, p);
            high = glm::max(high, p);
            vertices[3 * i] = p.x;
            vertices[3 * i + 1] = p.y;
            vertices[3 * i + 2] = p.z;
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                       RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                                       mesh.indices.size() / 3));
        std::copy(mesh.indices.begin(),
                  mesh.indices.begin() + static_cast<std::ptrdiff_t>(mesh.indices.size() / 3 * 3), indices);
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(sc, geometry);
        rtcReleaseGeometry(geometry);
    });
    rtcCommitScene(sc);
    if (rtcGetDeviceError(dev) != RTC_ERROR_NONE) {
        throw engine::Error("ground truth: Embree failed to build the scene");
    }
    sceneSize_ = low.x <= high.x ? std::max(glm::length(high - low), 1e-6f) : 1.0f;
}

RayTracedVisibility::~RayTracedVisibility() {
    rtcReleaseScene(scene(scene_));
    rtcReleaseDevice(device(device_));
}

void RayTracedVisibility::castShadowRays(std::span<const glm::vec3> origins,
                                         std::span<const glm::vec3> directions,
                                         std::span<const float> lengths, std::span<float> free) const {
    std::vector<RTCRay> rays(origins.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        RTCRay& ray = rays[i];
        ray.org_x = origins[i].x;
        ray.org_y = origins[i].y;
        ray.org_z = origins[i].z;
        ray.tnear = 0.0f;
        ray.dir_x = directions[i].x;
        ray.dir_y = directions[i].y;
        ray.dir_z = directions[i].z;
        ray.time = 0.0f;
        ray.tfar = lengths[i];
        ray.mask = ~0u;
        ray.id = static_cast<unsigned>(i);
        ray.flags = 0;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcOccluded1M(scene(scene_), &context, rays.data(), static_cast<unsigned>(rays.size()), sizeof(RTCRay));
    for (std::size_t i = 0; i < rays.size(); ++i) {
        // Embree marks an occluded ray by setting tfar to -inf.
        free[i] = rays[i].tfar >= 0.0f ? 1.0f : 0.0f;
    }
}

float RayTracedVisibility::rayOffset(const glm::vec3& position) const {
    const float sceneOffset = 1e-4f * sceneSize_;
    if (!viewer_) {
        return sceneOffset;
    }
    const glm::vec3 magnitude = glm::abs(position);
    return std::max(std::min(sceneOffset, 1e-4f * glm::length(position - *viewer_)),
                    1e-5f * std::max({magnitude.x, magnitude.y, magnitude.z}));
}

glm::vec3 RayTracedVisibility::rayOrigin(const glm::vec3& position, const glm::vec3& normal) const {
    return position + rayOffset(position) * facetNormal(position, normal);
}

glm::vec3 RayTracedVisibility::facetNormal(const glm::vec3& position, const glm::vec3& normal) const {
    if (!viewer_) {
        return normal;
    }
    // The triangle under the point: a short segment along the line of sight through it, starting a few
    // offsets in front (nothing nearer the viewer lies there, or it would have been seen instead).
    const glm::vec3 sight = position - *viewer_;
    const float distance = glm::length(sight);
    if (!(distance > 0.0f)) {
        return normal;
    }
    const glm::vec3 along = sight / distance;
    const float reach = 4.0f * rayOffset(position);
    RTCRayHit hit{};
    hit.ray.org_x = position.x - reach * along.x;
    hit.ray.org_y = position.y - reach * along.y;
    hit.ray.org_z = position.z - reach * along.z;
    hit.ray.dir_x = along.x;
    hit.ray.dir_y = along.y;
    hit.ray.dir_z = along.z;
    hit.ray.tnear = 0.0f;
    hit.ray.tfar = 2.0f * reach;
    hit.ray.mask = ~0u;
    hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene(scene_), &context, &hit);
    const glm::vec3 facet(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z);
    const float facetLength = glm::length(facet);
    if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID || !(facetLength > 0.0f)) {
        return normal;
    }
    return (glm::dot(facet, along) > 0.0f ? -facet : facet) / facetLength;
}

void RayTracedVisibility::hardVisibility(std::span<const glm::vec3> positions,
                                         std::span<const glm::vec3> normals,
                                         std::span<const std::uint8_t> covered,
                                         const engine::FrameLight& light, std::span<float> visibility) const {
    softVisibility(positions, normals, covered, light, 0.0f, 1, visibility);
}

void RayTracedVisibility::edgeWithin(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                     std::span<const float> reach, std::span<const std::uint8_t> lit,
                                     const engine::FrameLight& light, std::span<std::uint8_t> marked) const {
    constexpr int kDirections = 8;
    constexpr std::size_t kNoPath = std::numeric_limits<std::size_t>::max();
    RayBatch toLight;
    // From a lit receiver to each of its points: is the point on the receiver's side of every surface?
    RayBatch paths;
    // Per ray to the light, its point's path (kNoPath from a shadowed receiver).
    std::vector<std::size_t> pathOf;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        marked[i] = 0;
        if (!(reach[i] > 0.0f)) {
            continue;
        }
        const glm::vec3 onSurface = rayOrigin(positions[i], normals[i]);
        glm::vec3 towards;
        float length = 0.0f;
        towardsLight(light, positions[i], towards, length);
        glm::vec3 u;
        glm::vec3 v;
        basisAround(towards, u, v);
        for (const float distance : {0.5f * reach[i], reach[i]}) {
            for (int k = 0; k < kDirections; ++k) {
                const float angle =
                    glm::two_pi<float>() * static_cast<float>(k) / static_cast<float>(kDirections);
                const glm::vec3 across = std::cos(angle) * u + std::sin(angle) * v;
                const glm::vec3 origin = onSurface + distance * across;
                pathOf.push_back(lit[i] ? paths.origins.size() : kNoPath);
                if (lit[i]) {
                    paths.add(onSurface, across, distance, i);
                }
                glm::vec3 direction = towards;
                float segment = length;
                if (!std::isinf(length)) {
                    const glm::vec3 path = light.position - origin;
                    segment = glm::length(path);
                    direction = segment > 0.0f ? path / segment : towards;
                }
                toLight.add(origin, direction, segment, i);
            }
        }
    }
    std::vector<float> free(toLight.origins.size());
    castShadowRays(toLight.origins, toLight.directions, toLight.lengths, free);
    std::vector<float> clear(paths.origins.size());
    castShadowRays(paths.origins, paths.directions, paths.lengths, clear);
    for (std::size_t ray = 0; ray < free.size(); ++ray) {
        const std::size_t pixel = toLight.pixelOf[ray];
        const bool edge = lit[pixel] ? free[ray] <= 0.5f && clear[pathOf[ray]] > 0.5f : free[ray] > 0.5f;
        marked[pixel] |= static_cast<std::uint8_t>(edge);
    }
}

float RayTracedVisibility::ownRadius(const engine::FrameLight& light) {
    return light.light.type == engine::LightType::Directional ? 0.5f * light.light.angularDiameter
                                                              : light.light.radius;
}

namespace {
/// π (3 - √5): successive points of a Fibonacci lattice turn by it.
constexpr double kGoldenAngle = 2.39996322972865332;
} // namespace

void RayTracedVisibility::softVisibility(std::span<const glm::vec3> positions,
                                         std::span<const glm::vec3> normals,
                                         std::span<const std::uint8_t> covered,
                                         const engine::FrameLight& light, float radius, int samplesPerAxis,
                                         std::span<float> visibility) const {
    const int samples = radius > 0.0f ? std::max(samplesPerAxis, 1) : 1;
    const float weight = 1.0f / static_cast<float>(samples * samples);
    // Cast a batch at a time: a 640x480 view at 32² rays per pixel would hold 300 M rays at once.
    constexpr std::size_t kBatchRays = std::size_t{1} << 20;
    RayBatch batch;
    std::vector<float> free;
    const auto cast = [&] {
        free.resize(batch.origins.size());
        castShadowRays(batch.origins, batch.directions, batch.lengths, free);
        for (std::size_t ray = 0; ray < free.size(); ++ray) {
            visibility[batch.pixelOf[ray]] += free[ray] * weight;
        }
        batch = {};
    };
    for (std::size_t i = 0; i < positions.size(); ++i) {
        visibility[i] = 0.0f;
        if (!covered[i]) {
            continue;
        }
        const glm::vec3 origin = rayOrigin(positions[i], normals[i]);
        glm::vec3 direction;
        float length = 0.0f;
        towardsLight(light, positions[i], direction, length);
        const bool sun = std::isinf(length);
        if (!sun && radius >= length) {
            visibility[i] = 1.0f; // inside the light's sphere: nothing lies between
            continue;
        }
        // The light seen from the point: a cone of half-angle `radius` (a sun's angular radius), or the one a
        // sphere of `radius` subtends at distance `length`.
        const double cosMax = sun ? std::cos(static_cast<double>(radius))
                                  : std::sqrt(1.0 - static_cast<double>(radius) * radius /
                                                        (static_cast<double>(length) * length));
        glm::vec3 u;
        glm::vec3 v;
        basisAround(direction, u, v);
        const int rays = samples * samples;
        for (int k = 0; k < rays; ++k) {
            glm::vec3 target = direction;
            float segment = length;
            if (rays > 1) {
                // A Fibonacci lattice over the cone, uniform in solid angle: ray k alone in the k-th of
                // `rays` rings of equal solid angle (cos θ evenly spaced from 1 to cos θmax), turned by the
                // golden angle from the one before. Every straight shadow edge across the light then cuts the
                // rays in proportion to the part it hides far more evenly than a grid of strata does (error
                // about 1/rays rather than 1/samples).
                const double cosine = 1.0 - (k + 0.5) / rays * (1.0 - cosMax);
                const double sine = std::sqrt(std::max(0.0, 1.0 - cosine * cosine));
                const double angle = k * kGoldenAngle;
                target = glm::normalize(
                    glm::vec3(cosine * glm::dvec3(direction) +
                              sine * (std::cos(angle) * glm::dvec3(u) + std::sin(angle) * glm::dvec3(v))));
                if (!sun) {
                    // To the sphere's near surface along the ray: d cos α - sqrt(r² - d² sin² α).
                    const double d = length;
                    const double inside = static_cast<double>(radius) * radius - d * d * sine * sine;
                    segment = static_cast<float>(d * cosine - std::sqrt(std::max(0.0, inside)));
                }
            }
            batch.add(origin, target, segment, i);
        }
        if (batch.origins.size() >= kBatchRays) {
            cast();
        }
    }
    cast();
}

} // namespace shadowbench
