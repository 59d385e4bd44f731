// --camera "x,y,z,yawDeg,pitchDeg[,fovYDeg]" parsing (the interface contract's numeric form).
#include "scene/camera.hpp"

#include "scene/errors.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace ppr::scene {

namespace {

std::string trim(const std::string& s) {
    const size_t b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// strtod accepts "nan"/"inf", so those count as numbers here (and are rejected as not finite).
bool toNumber(const std::string& token, double& out) {
    if (token.empty()) return false;
    char* end = nullptr;
    out = std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size();
}

}  // namespace

std::optional<CameraPose> parseCameraSpec(const std::string& text) {
    std::vector<std::string> tokens;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        tokens.push_back(trim(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    // Numeric form: the first field is a number and either a comma follows or it is written like one
    // (a lone "inf" or "nan" is more plausibly a camera name). Anything else names a camera.
    double first = 0.0;
    const char c0 = tokens[0].empty() ? '\0' : tokens[0][0];
    const bool looksNumeric = std::isdigit(static_cast<unsigned char>(c0)) || c0 == '-' || c0 == '+' || c0 == '.';
    if (!toNumber(tokens[0], first) || (tokens.size() == 1 && !looksNumeric)) return std::nullopt;

    const std::string got = " (got '" + text + "')";
    std::vector<double> v;
    for (const auto& t : tokens) {
        double d = 0.0;
        if (!toNumber(t, d)) detail::fail("--camera: '" + t + "' is not a number; expected x,y,z,yawDeg,pitchDeg[,fovYDeg]" + got);
        v.push_back(d);
    }
    if (v.size() != 5 && v.size() != 6)
        detail::fail("--camera: expected 5 or 6 comma-separated numbers x,y,z,yawDeg,pitchDeg[,fovYDeg], got " +
                     std::to_string(v.size()) + got);
    static const char* kNames[] = {"x", "y", "z", "yawDeg", "pitchDeg", "fovYDeg"};
    // Judged as stored (floats): 1e30 is a float a little over 1e30, which written back would fail.
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]) || !(std::abs(static_cast<float>(v[i])) <= 1e30f))
            detail::fail(std::string("--camera: ") + kNames[i] + ": not a finite number" + got);
    CameraPose pose;
    pose.position = glm::vec3(v[0], v[1], v[2]);
    pose.yawDeg = static_cast<float>(v[3]);
    pose.pitchDeg = static_cast<float>(v[4]);
    if (v[4] < -90.0 || v[4] > 90.0)
        detail::fail("--camera: pitchDeg: " + detail::fmtNum(v[4]) + " out of range [-90, 90]" + got);
    if (v.size() == 6) {
        // Judged as stored: 1.00000000001 is a float of exactly 1, outside the open range.
        pose.fovYDeg = static_cast<float>(v[5]);
        if (!(pose.fovYDeg > 1.0f && pose.fovYDeg < 179.0f))
            detail::fail("--camera: fovYDeg: " + detail::fmtNum(v[5]) + " out of range (1, 179)" + got);
    }
    return pose;
}

}  // namespace ppr::scene
