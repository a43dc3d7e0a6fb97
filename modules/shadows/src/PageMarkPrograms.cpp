#include "PageMarkPrograms.h"

#include <array>
#include <string>
#include <vector>

namespace shadows {

const engine::gl::Program& PageMarkPrograms::forFaces(int faces) {
    std::unique_ptr<engine::gl::Program>& program = faces > 0 ? perspective_ : clipmap_;
    if (!program) {
        const std::string define = faces > 0 ? "GS_PAGES_PERSPECTIVE" : "GS_PAGES_CLIPMAP";
        const std::vector<std::string> defines{"#define " + define};
        const std::array stages{shaders_.preprocess(GL_COMPUTE_SHADER, "shadows/pages.comp", defines)};
        program = std::make_unique<engine::gl::Program>("shadows/pages.comp [" + define + "]", stages);
    }
    return *program;
}

} // namespace shadows
