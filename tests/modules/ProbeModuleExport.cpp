#include "ProbeModule.h"

GS_EXPORT_MODULE("probe", ProbeModule)

/// Lets tests read the events of a probe created by this library.
extern "C" __attribute__((visibility("default"))) const std::vector<std::string>*
gsProbeEvents(const engine::Module* module) {
    return &static_cast<const ProbeModule*>(module)->events;
}
