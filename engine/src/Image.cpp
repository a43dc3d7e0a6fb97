#include <engine/Error.h>
#include <engine/Image.h>

#include <stb/stb_image_write.h>

#include <fstream>
#include <string>
#include <unistd.h>

namespace engine {

glm::u8vec4 Image::at(int x, int y) const {
    const std::size_t offset = (static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + x) * 4;
    return {pixels[offset], pixels[offset + 1], pixels[offset + 2], pixels[offset + 3]};
}

namespace {

std::filesystem::path temporaryBeside(const std::filesystem::path& path) {
    return path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(::getpid()));
}

void prepareParent(const std::filesystem::path& path) {
    std::error_code error;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), error);
        if (error) {
            throw IoError(path.string() + ": cannot create folder " + path.parent_path().string() + ": " +
                          error.message());
        }
    }
}

void commit(const std::filesystem::path& temporary, const std::filesystem::path& path) {
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw IoError(path.string() + ": cannot move the finished file into place: " + error.message());
    }
}

} // namespace

void writePng(const std::filesystem::path& path, const Image& image) {
    if (image.size.x <= 0 || image.size.y <= 0 ||
        image.pixels.size() !=
            static_cast<std::size_t>(image.size.x) * static_cast<std::size_t>(image.size.y) * 4) {
        throw IoError(path.string() + ": image has no pixels or a size that does not match its data");
    }
    prepareParent(path);
    const std::filesystem::path temporary = temporaryBeside(path);
    if (!stbi_write_png(temporary.c_str(), image.size.x, image.size.y, 4, image.pixels.data(),
                        image.size.x * 4)) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw IoError(path.string() + ": cannot write PNG");
    }
    commit(temporary, path);
}

void writeTextFile(const std::filesystem::path& path, std::string_view text) {
    prepareParent(path);
    const std::filesystem::path temporary = temporaryBeside(path);
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!out.flush()) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw IoError(path.string() + ": cannot write file");
        }
    }
    commit(temporary, path);
}

} // namespace engine
