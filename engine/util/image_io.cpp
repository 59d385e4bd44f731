#include "util/image_io.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>

namespace ppr::util {

void writePng(const std::string& path, const Rgba8Image& image) {
    if (image.pixels.size() != size_t(image.width) * image.height * 4) throw std::runtime_error(path + ": image size mismatch");
    if (!stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height), 4, image.pixels.data(),
                        static_cast<int>(image.width * 4)))
        throw std::runtime_error(path + ": cannot write PNG");
}

Rgba8Image readPng(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 4);
    if (!data) throw std::runtime_error(path + ": cannot read image (" + stbi_failure_reason() + ")");
    Rgba8Image img;
    img.width = static_cast<uint32_t>(w);
    img.height = static_cast<uint32_t>(h);
    img.pixels.assign(data, data + size_t(w) * h * 4);
    stbi_image_free(data);
    return img;
}

}  // namespace ppr::util
