#pragma once

#include <shadowbench/ShadowBench.h>

#include <glm/vec2.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace shadowbench {

/// @brief One run of the OpenSceneGraph peer (tools/osgpeer) on a scene: what its PREFIX.json and
/// PREFIX.visibility.pfm hold.
struct PeerRun {
    /// The run's name, its files' stem: a technique ("vdsm", "sm", "lispsm", "ssm") or any name a run was
    /// given, e.g. "pssm3" or "vdsm-csm2"; the row label is "osg-" + technique.
    std::string technique;
    /// The osgShadow class it ran, e.g. "osgShadow::ViewDependentShadowMap".
    std::string osgClass;
    std::string renderer;
    int mapSize = 0;
    /// Shadow maps drawn per frame (splits or cascades); 1 for runs that predate the field.
    int shadowMaps = 1;
    PassTiming shadowed;
    PassTiming unshadowed;
    /// Whether the peer raised glibc's allocator thresholds as our context does (gs-osgshadow --allocator);
    /// empty for runs that predate the field.
    std::optional<bool> allocatorTuned;
    /// Visibility per pixel, rows top to bottom (our images' order), in [0,1], or -1 where the peer's
    /// unshadowed frame had no lit surface.
    std::vector<float> visibility;
};

/// @brief The peer's runs to look for in `<folder>/<scene>/`, in table order: the four single-map techniques
/// (vdsm, sm, lispsm, ssm) whether present or not, so a missing one can be reported, then the name of every
/// other `<name>.json` there (e.g. pssm3, vdsm-csm2), sorted. A missing folder gives just the four.
[[nodiscard]] std::vector<std::string> peerRunNames(const std::filesystem::path& folder,
                                                    const std::string& scene);

/// @brief Reads `<folder>/<scene>/<technique>.json` and `.visibility.pfm`; nullopt when the JSON is absent.
/// Throws engine::Error naming the file and field when either is malformed or the image is not `size`.
std::optional<PeerRun> loadPeerRun(const std::filesystem::path& folder, const std::string& scene,
                                   const std::string& technique, glm::ivec2 size);

} // namespace shadowbench
