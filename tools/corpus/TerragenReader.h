#pragma once

#include <engine/MeshData.h>

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace corpus {

/// @brief A regular grid of elevations in metres, rows along +Y of the file (x fastest).
struct Heightfield {
    int columns = 0;
    int rows = 0;
    /// Metres between neighbouring grid points along x, y (the file's horizontal axes).
    float spacing = 30.0f;
    std::vector<float> elevations;
};

/// @brief Reads Terragen terrain files (.ter): the "TERRAGENTERRAIN " header, then SIZE, XPTS, YPTS, SCAL,
/// CRAD, CRVM and ALTW chunks up to "EOF ". Elevation in metres = (BaseHeight + value · HeightScale / 65536)
/// · SCAL.z, after the format's published description (Planetside Software, "Terragen Terrain File
/// Specification"). Throws content::ContentError naming `source` and the chunk on malformed input.
Heightfield readTerragen(std::span<const std::uint8_t> bytes, const std::string& source);
Heightfield readTerragen(const std::filesystem::path& path);

/// @brief Triangulates `field` (two triangles per cell, smooth normals from central differences) in a Y-up
/// frame centred on the origin: file x → +X, file y → −Z, elevation → +Y.
engine::MeshData heightfieldMesh(const Heightfield& field);

} // namespace corpus
