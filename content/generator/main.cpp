// ppr_make_default_scene <out-dir>: writes the default scene (glTF + bin + PNGs + reflector file).
// Run at build time; output is byte-identical from run to run.
#include "default_scene.hpp"

#include <exception>
#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: ppr_make_default_scene <output-directory>\n";
        return 2;
    }
    try {
        std::filesystem::create_directories(argv[1]);
        gen::writeDefaultScene(argv[1]);
    } catch (const std::exception& e) {
        std::cerr << "ppr_make_default_scene: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
