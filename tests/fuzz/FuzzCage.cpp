// Fuzz target: every input is parsed both as an OBJ and as an OFF cage through CageLoader::loadFromMemory.
// A cage the loader accepts must also subdivide: Cage::validate() promises OpenSubdiv a usable cage.
#include <content/CageLoader.h>
#include <content/ContentError.h>
#include <content/SubdivisionSurface.h>

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const auto format : {content::CageLoader::Format::Obj, content::CageLoader::Format::Off}) {
        try {
            content::Cage cage = content::CageLoader::loadFromMemory(text, format, "fuzz-cage");
            // Level 1 reaches every OpenSubdiv code path the cage's topology selects, at little cost.
            (void)content::SubdivisionSurface(std::move(cage)).evaluate(1);
        } catch (const content::ContentError&) {
        }
    }
    return 0;
}
