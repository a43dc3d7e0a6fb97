#include <engine/AtomicFile.h>
#include <engine/Error.h>

#include <string>
#include <unistd.h>

namespace engine {

void writeAtomically(const std::filesystem::path& path,
                     const std::function<bool(const std::filesystem::path& temporary)>& write) {
    std::error_code error;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), error);
        if (error) {
            throw IoError(path.string() + ": cannot create folder " + path.parent_path().string() + ": " +
                          error.message());
        }
    }
    // The process id keeps concurrent writers of the same file from sharing a temporary.
    const std::filesystem::path temporary =
        path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()));
    if (!write(temporary)) {
        std::filesystem::remove(temporary, error);
        throw IoError(path.string() + ": cannot write file");
    }
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw IoError(path.string() + ": cannot move the finished file into place: " + error.message());
    }
}

} // namespace engine
