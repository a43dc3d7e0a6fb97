#pragma once

#include "content/Cage.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace content {

/// @brief Builders for closed, all-quad control cages with outward (counter-clockwise) faces.
class CageShapes {
public:
    /// @brief Profile of a surface of revolution around the +Y axis.
    struct LatheProfile {
        /// @brief Ring (radius, height) pairs, from the bottom pole to the top pole, all radii > 0. The solid
        /// must lie to the left of the profile when walking it in order in the (radius, height) half-plane,
        /// so a profile that turns back down (the inside wall of a bowl) gives an inward-facing wall.
        std::vector<glm::vec2> rings;
        /// @brief Height of the bottom cap's centre; the cap bulges from the first ring towards it.
        float bottomPoleHeight = 0.0f;
        /// @brief Height of the top cap's centre; the cap bulges from the last ring towards it.
        float topPoleHeight = 0.0f;
    };

    /// @brief Axis-aligned box centred on the origin, each side split into a grid of quads.
    /// @param segments Quads along X, Y and Z (each at least 1).
    /// @param size Edge lengths along X, Y and Z.
    [[nodiscard]] static Cage box(glm::ivec3 segments, glm::vec3 size);

    /// @brief Cube grid projected onto a sphere centred on the origin.
    /// @param segmentsPerEdge Quads along each cube edge (at least 1).
    [[nodiscard]] static Cage quadSphere(int segmentsPerEdge, float radius);

    /// @brief Torus around the +Y axis centred on the origin.
    /// @param ringSegments Quads around the main ring (at least 3).
    /// @param tubeSegments Quads around the tube (at least 3).
    [[nodiscard]] static Cage torus(int ringSegments, int tubeSegments, float majorRadius, float minorRadius);

    /// @brief Closed surface of revolution: quad bands between rings, closed at each pole by a quad grid.
    ///
    /// The caps are (segments/4 + 1)^2 vertex grids whose border is the end ring, so the cage stays all-quad
    /// without a high-valence pole vertex.
    /// @param segments Quads around the axis; a multiple of 4, at least 4.
    [[nodiscard]] static Cage lathe(const LatheProfile& profile, int segments);
};

} // namespace content
