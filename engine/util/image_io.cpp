#include "util/image_io.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <fstream>
#include <stdexcept>

namespace ppr::util {

void writePng(const std::string& path, const Rgba8Image& image) {
    if (image.pixels.size() != size_t(image.width) * image.height * 4) throw std::runtime_error(path + ": image size mismatch");
    // Encoded in memory, then written with every failure checked: stbi_write_png ignores fwrite's
    // result, so a full disk would leave a truncated PNG behind without a word.
    std::string png;
    auto append = [](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<const char*>(data), size_t(size)); };
    if (!stbi_write_png_to_func(append, &png, static_cast<int>(image.width), static_cast<int>(image.height), 4, image.pixels.data(),
                                static_cast<int>(image.width * 4)))
        throw std::runtime_error(path + ": cannot encode PNG");
    std::ofstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error(path + ": cannot open for writing");
    f.write(png.data(), std::streamsize(png.size()));
    f.flush();
    if (!f) throw std::runtime_error(path + ": write failed");
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
