#pragma once

#include <content/GltfLoader.h>

namespace corpus {

/// @brief How the generated apron scene is written.
struct ApronOptions {
    /// Bake every object, the ground included, into one mesh on one node (as real assets often arrive)
    /// instead of one mesh and node per object. The triangles are the same either way.
    bool merged = false;
    /// Sun elevation above the horizon and azimuth around +Y from the camera's side (+Z), degrees.
    float sunElevation = 8.0f;
    float sunAzimuth = 75.0f;
};

/// @brief A generated airport apron for shadow benchmarks of large outdoor views: a 300 m concrete ground
/// centred on the origin (y up) with about 70 objects of 1-40 m (an aircraft, buses, trucks, tugs, baggage
/// carts, containers, some on stands), light poles with cross-arms, overhead wires and a fence; a camera 8 m
/// above the ground near the +Z edge looking across it, and a low shadow-casting sun. Deterministic: the same
/// options give the same scene on every run and build.
content::LoadedScene apronScene(const ApronOptions& options);

} // namespace corpus
