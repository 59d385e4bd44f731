// Camera path files: parseCameraPath (engine/scene/camera_path.cpp), the parser behind
// `--path FILE` for capture and compare: one pose "x,y,z,yawDeg,pitchDeg[,fovYDeg]" per line, blank
// lines and # comments skipped. The input is the file's text. What parses must be poses the renderer
// can use (finite, pitch within ±90°, field of view within (1°, 179°)), and written back one per line
// at full precision they must parse to the same poses.
#include "fuzz_check.hpp"

#include "scene/camera_path.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using namespace ppr;

namespace {

bool same(const scene::CameraPose& a, const scene::CameraPose& b) {
    return a.position == b.position && a.yawDeg == b.yawDeg && a.pitchDeg == b.pitchDeg && a.fovYDeg == b.fovYDeg;
}

std::string line(const scene::CameraPose& p) {
    char text[256];
    std::snprintf(text, sizeof text, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", p.position.x, p.position.y, p.position.z, p.yawDeg,
                  p.pitchDeg, p.fovYDeg);
    return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<scene::CameraPose> poses;
    try {
        poses = scene::parseCameraPath(text, "fuzz.path");
    } catch (const std::runtime_error& e) {
        fuzz::checkOneLine(e);
        return 0;
    }
    fuzz::check(!poses.empty(), "a path without poses was accepted");
    std::string written;
    for (const scene::CameraPose& p : poses) {
        fuzz::check(std::isfinite(p.position.x) && std::isfinite(p.position.y) && std::isfinite(p.position.z) &&
                        std::isfinite(p.yawDeg) && p.pitchDeg >= -90.0f && p.pitchDeg <= 90.0f && p.fovYDeg > 1.0f &&
                        p.fovYDeg < 179.0f,
                    "accepted a pose the renderer cannot use: " + line(p));
        written += line(p);
    }
    std::vector<scene::CameraPose> again;
    try {
        again = scene::parseCameraPath(written, "fuzz.path");
    } catch (const std::runtime_error& e) {
        fuzz::broken(std::string("written back, the path no longer parses: ") + e.what());
    }
    fuzz::check(again.size() == poses.size(), "written back, the path has another number of poses");
    for (size_t i = 0; i < poses.size(); ++i) fuzz::check(same(again[i], poses[i]), "written back, a pose changed: " + line(poses[i]));
    fuzz::check(scene::isStill(again) == scene::isStill(poses), "isStill differs between equal paths");
    return 0;
}
