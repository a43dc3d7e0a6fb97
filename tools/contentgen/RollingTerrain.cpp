#include "RollingTerrain.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace contentgen {

RollingTerrain::RollingTerrain(float size, int tiles, int quadsPerTile)
    : size_(size), tiles_(tiles), quadsPerTile_(quadsPerTile),
      cell_(size / static_cast<float>(tiles * quadsPerTile)) {}

namespace {

/// A round hill: height · exp(-r² / (2 sigma²)) around (x, z).
struct Hill {
    float x;
    float z;
    float height;
    float sigma;
};

// Three hills on the skyline (1.5 to 2 km from the origin); their steepest slope is 0.61 height / sigma, at
// most 0.13 (7°).
constexpr Hill kHills[] = {
    {-900.0f, -1700.0f, 90.0f, 450.0f}, {700.0f, -1500.0f, 60.0f, 400.0f}, {1500.0f, 500.0f, 110.0f, 500.0f}};

float hillHeight(const Hill& hill, float x, float z) {
    const float dx = x - hill.x;
    const float dz = z - hill.z;
    return hill.height * std::exp(-(dx * dx + dz * dz) / (2.0f * hill.sigma * hill.sigma));
}

} // namespace

float RollingTerrain::field(float x, float z) {
    float height = 11.0f * std::sin(x / 260.0f + 0.4f) * std::cos(z / 230.0f - 0.3f) +
                   3.0f * std::sin((x + z) / 140.0f) +
                   14.0f * std::sin(x / 900.0f) * std::sin(z / 1100.0f + 1.0f);
    for (const Hill& hill : kHills) {
        height += hillHeight(hill, x, z);
    }
    return height;
}

glm::vec3 RollingTerrain::fieldNormal(float x, float z) {
    // The normal of y = f(x, z) is (-df/dx, 1, -df/dz), normalised; the derivatives of field() by hand.
    float dx = 11.0f / 260.0f * std::cos(x / 260.0f + 0.4f) * std::cos(z / 230.0f - 0.3f) +
               3.0f / 140.0f * std::cos((x + z) / 140.0f) +
               14.0f / 900.0f * std::cos(x / 900.0f) * std::sin(z / 1100.0f + 1.0f);
    float dz = -11.0f / 230.0f * std::sin(x / 260.0f + 0.4f) * std::sin(z / 230.0f - 0.3f) +
               3.0f / 140.0f * std::cos((x + z) / 140.0f) +
               14.0f / 1100.0f * std::sin(x / 900.0f) * std::cos(z / 1100.0f + 1.0f);
    for (const Hill& hill : kHills) {
        const float scale = -hillHeight(hill, x, z) / (hill.sigma * hill.sigma);
        dx += scale * (x - hill.x);
        dz += scale * (z - hill.z);
    }
    return glm::normalize(glm::vec3(-dx, 1.0f, -dz));
}

glm::vec3 RollingTerrain::gridPoint(int i, int j) const {
    const float x = -0.5f * size_ + cell_ * static_cast<float>(i);
    const float z = -0.5f * size_ + cell_ * static_cast<float>(j);
    return {x, field(x, z), z};
}

float RollingTerrain::height(float x, float z) const {
    const int last = tiles_ * quadsPerTile_;
    const float gx = std::clamp((x + 0.5f * size_) / cell_, 0.0f, static_cast<float>(last));
    const float gz = std::clamp((z + 0.5f * size_) / cell_, 0.0f, static_cast<float>(last));
    const int i = std::min(static_cast<int>(gx), last - 1);
    const int j = std::min(static_cast<int>(gz), last - 1);
    const float u = gx - static_cast<float>(i);
    const float v = gz - static_cast<float>(j);
    // Each quad is split along its (i+1, j)-(i, j+1) diagonal, as tile() triangulates it.
    const float h00 = gridPoint(i, j).y;
    const float h10 = gridPoint(i + 1, j).y;
    const float h01 = gridPoint(i, j + 1).y;
    const float h11 = gridPoint(i + 1, j + 1).y;
    if (u + v <= 1.0f) {
        return h00 + u * (h10 - h00) + v * (h01 - h00);
    }
    return h11 + (1.0f - u) * (h01 - h11) + (1.0f - v) * (h10 - h11);
}

float RollingTerrain::lowestUnder(float x, float z, float halfWidth) const {
    // The ground is linear inside each triangle, so its minimum over the square lies at a grid vertex inside
    // it or at a corner of the square or where the square's edges cross grid lines or quad diagonals: every
    // one of those is evaluated. Grid coordinates: world / cell, origin at the ground's corner.
    const auto toGrid = [&](float world) { return (world + 0.5f * size_) / cell_; };
    const auto toWorld = [&](float grid) { return grid * cell_ - 0.5f * size_; };
    const float x0 = toGrid(x - halfWidth);
    const float x1 = toGrid(x + halfWidth);
    const float z0 = toGrid(z - halfWidth);
    const float z1 = toGrid(z + halfWidth);
    float lowest = height(x, z);
    for (float i = std::ceil(x0); i <= x1; i += 1.0f) {
        for (float j = std::ceil(z0); j <= z1; j += 1.0f) {
            lowest = std::min(lowest, height(toWorld(i), toWorld(j)));
        }
    }
    // Along an edge where one grid coordinate is `fixed`, the other crosses grid lines at whole numbers and
    // diagonals (grid x + grid z whole) at whole numbers minus `fixed`.
    const auto edge = [&](float fixed, float from, float to, bool alongX) {
        const float diagonal = std::ceil(fixed) - fixed;
        const auto visit = [&](float t) {
            if (t >= from && t <= to) {
                lowest = std::min(lowest, alongX ? height(toWorld(t), toWorld(fixed))
                                                 : height(toWorld(fixed), toWorld(t)));
            }
        };
        visit(from);
        visit(to);
        for (float whole = std::floor(from); whole <= to; whole += 1.0f) {
            visit(whole);
            visit(whole + diagonal);
        }
    };
    edge(z0, x0, x1, true);
    edge(z1, x0, x1, true);
    edge(x0, z0, z1, false);
    edge(x1, z0, z1, false);
    return lowest;
}

glm::vec3 RollingTerrain::tileCentre(int column, int row) const {
    const float tileSize = size_ / static_cast<float>(tiles_);
    return {-0.5f * size_ + tileSize * (static_cast<float>(column) + 0.5f), 0.0f,
            -0.5f * size_ + tileSize * (static_cast<float>(row) + 0.5f)};
}

engine::MeshData RollingTerrain::tile(int column, int row) const {
    engine::MeshData mesh;
    mesh.name = "ground tile";
    const glm::vec3 centre = tileCentre(column, row);
    for (int j = 0; j <= quadsPerTile_; ++j) {
        for (int i = 0; i <= quadsPerTile_; ++i) {
            const glm::vec3 p = gridPoint(column * quadsPerTile_ + i, row * quadsPerTile_ + j);
            mesh.positions.push_back(p - centre);
            mesh.normals.push_back(fieldNormal(p.x, p.z));
        }
    }
    const auto stride = static_cast<std::uint32_t>(quadsPerTile_ + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(quadsPerTile_); ++j) {
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(quadsPerTile_); ++i) {
            const std::uint32_t k = j * stride + i;
            // Counter-clockwise seen from above; the diagonal runs from (i+1, j) to (i, j+1).
            mesh.indices.insert(mesh.indices.end(),
                                {k, k + stride, k + 1, k + 1, k + stride, k + stride + 1});
        }
    }
    return mesh;
}

} // namespace contentgen
