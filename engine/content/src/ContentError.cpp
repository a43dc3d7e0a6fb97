#include "content/ContentError.h"

namespace content {

ContentError::ContentError(const std::string& source, const std::string& detail)
    : engine::Error(source + ": " + detail) {}

} // namespace content
