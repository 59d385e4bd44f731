#pragma once
// PPR_VIEWER_SOAK=1: the viewer drives itself as a restless user would, for the soak
// (scripts/soak.sh, docs/reliability.md): it cycles the techniques, sets every declared setting to
// random values from its choices or range (debug views included), picks render scales, resizes the
// window, and iconifies and restores it. Deterministic (a fixed seed) so a soak that finds a problem
// can be replayed. Every kCycle frames it comes home for kHome frames (the first technique, default
// settings, the initial window size and render scale) and asks for a memory sample at the end: the
// soak compares those samples, taken in the same state, since the graph's transient pool rightly
// follows the frame's size and settings.
// It starts with a warm-up: every choice of every declared setting once, one a frame, with the first
// technique, so that what is made once when a value is first asked for (a workgroup width's
// pipeline) is made before the first sample, as the headless soak's warm-up frames make theirs.
#include "settings/settings.hpp"

#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

struct GLFWwindow;

namespace ppr::app {

class ViewerSoak {
public:
    static constexpr uint64_t kCycle = 600, kHome = 150;

    // Called once per loop iteration (`frame` = frames presented so far). True when a memory sample
    // should be taken now (the end of a home stretch).
    bool advance(uint64_t frame, GLFWwindow* window, Settings& settings, std::string& technique, float& renderScale);

private:
    std::string homeTechnique_;
    int homeWidth_ = 0, homeHeight_ = 0;
    float homeRenderScale_ = 1.0f;
    std::mt19937 rng_{20261124u};
    uint64_t lastFrame_ = ~0ull;
    int iconifiedFor_ = 0;  // loop iterations left before restoring
    std::vector<std::pair<std::string, std::string>> warmup_;  // (key, choice) for each frame of the warm-up
};

}  // namespace ppr::app
