#include <engine/Module.h>

namespace {
class WrongAbiModule final : public engine::Module {
public:
    [[nodiscard]] std::string_view name() const override { return "wrong_abi"; }
};
} // namespace

extern "C" __attribute__((visibility("default"))) const engine::ModuleDescriptor* gsModuleDescriptor() {
    static const engine::ModuleDescriptor descriptor{engine::kModuleAbiVersion + 1, GS_MODULE_BUILD_TAG,
                                                     "wrong_abi",
                                                     []() -> engine::Module* { return new WrongAbiModule(); },
                                                     [](engine::Module* module) { delete module; }};
    return &descriptor;
}
