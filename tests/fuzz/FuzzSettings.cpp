// Fuzz target: shadow settings JSON through shadows::settingsFromJson. Accepted settings must survive a
// round trip through settingsToJson unchanged.
#include <shadows/ShadowSettingsJson.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const shadows::ShadowSettings settings = shadows::settingsFromJson(text, "fuzz.json");
        if (!(shadows::settingsFromJson(shadows::settingsToJson(settings), "round trip") == settings)) {
            std::abort();
        }
    } catch (const shadows::SettingsError&) {
    }
    return 0;
}
