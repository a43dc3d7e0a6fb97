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
    /// "vdsm", "sm", "lispsm" or "ssm"; the row label is "osg-" + technique.
    std::string technique;
    /// The osgShadow class it ran, e.g. "osgShadow::ViewDependentShadowMap".
    std::string osgClass;
    std::string renderer;
    int mapSize = 0;
    PassTiming shadowed;
    PassTiming unshadowed;
    /// Visibility per pixel, rows top to bottom (our images' order), in [0,1], or -1 where the peer's
    /// unshadowed frame had no lit surface.
    std::vector<float> visibility;
};

/// @brief The techniques the peer runs, in table order.
const std::vector<std::string>& peerTechniques();

/// @brief Reads `<folder>/<scene>/<technique>.json` and `.visibility.pfm`; nullopt when the JSON is absent.
/// Throws engine::Error naming the file and field when either is malformed or the image is not `size`.
std::optional<PeerRun> loadPeerRun(const std::filesystem::path& folder, const std::string& scene,
                                   const std::string& technique, glm::ivec2 size);

} // namespace shadowbench
