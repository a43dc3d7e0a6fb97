#include <engine/AtomicFile.h>
#include <engine/Error.h>
#include <engine/Image.h>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <fstream>

namespace engine {

glm::u8vec4 Image::at(int x, int y) const {
    const std::size_t offset = (static_cast<std::size_t>(y) * static_cast<std::size_t>(size.x) + x) * 4;
    return {pixels[offset], pixels[offset + 1], pixels[offset + 2], pixels[offset + 3]};
}

void writePng(const std::filesystem::path& path, const Image& image) {
    if (image.size.x <= 0 || image.size.y <= 0 ||
        image.pixels.size() !=
            static_cast<std::size_t>(image.size.x) * static_cast<std::size_t>(image.size.y) * 4) {
        throw IoError(path.string() + ": image has no pixels or a size that does not match its data");
    }
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        return stbi_write_png(temporary.c_str(), image.size.x, image.size.y, 4, image.pixels.data(),
                              image.size.x * 4) != 0;
    });
}

Image readPng(const std::filesystem::path& path) {
    int width = 0;
    int height = 0;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &width, &height, &channels, 4);
    if (!data) {
        throw IoError(path.string() + ": cannot read the image (" + stbi_failure_reason() + ")");
    }
    Image image;
    image.size = {width, height};
    image.pixels.assign(data, data + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(data);
    return image;
}

void writeTextFile(const std::filesystem::path& path, std::string_view text) {
    writeAtomically(path, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        return static_cast<bool>(out.flush());
    });
}

} // namespace engine
