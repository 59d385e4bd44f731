// ppr_make_default_scene [--scale[=SEGMENTS]] <out-dir>: writes the default scene (glTF + bin + PNGs +
// reflector file), or with --scale the scale scene (content/generator/scale_scene.hpp; SEGMENTS per
// sphere, default 32). Run at build time (the default scene) and by scripts/scale-scene.sh; output is
// byte-identical from run to run.
#include "default_scene.hpp"
#include "scale_scene.hpp"

#include <exception>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
    const std::string option = argc == 3 ? argv[1] : "";
    const bool scale = option == "--scale" || option.rfind("--scale=", 0) == 0;
    if (argc != 2 && !scale) {
        std::cerr << "usage: ppr_make_default_scene [--scale[=SEGMENTS]] <output-directory>\n";
        return 2;
    }
    const std::string dir = argv[argc - 1];
    try {
        std::filesystem::create_directories(dir);
        int segments = gen::kScaleDefaultSegments;
        if (scale && option != "--scale") {
            const std::string text = option.substr(8);
            if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 3)
                throw std::runtime_error(option + ": expected a whole number of segments");
            segments = std::stoi(text);
        }
        if (scale) gen::writeScaleScene(dir, segments);
        else gen::writeDefaultScene(dir);
    } catch (const std::exception& e) {
        std::cerr << "ppr_make_default_scene: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
