#pragma once
// PNG in/out (stb, from Debian's libstb). Errors throw std::runtime_error naming the file.
#include <cstdint>
#include <string>
#include <vector>

namespace ppr::util {

struct Rgba8Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> pixels;  // width * height * 4
};

void writePng(const std::string& path, const Rgba8Image& image);
Rgba8Image readPng(const std::string& path);

}  // namespace ppr::util
