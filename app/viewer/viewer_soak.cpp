#include "viewer/viewer_soak.hpp"

#include "render/render_scale.hpp"
#include "viewer/viewer_ui.hpp"

#include <GLFW/glfw3.h>

#include <cstdio>

namespace ppr::app {

namespace {

// A value for a declared setting: one of its choices, or its range's minimum or default. (The maxima
// — 8192² shadow maps and atlases — are the validation sweep's business; here they would only slow
// the soak to a few frames a minute on a CPU device.)
std::string randomValue(const SettingDecl& d, std::mt19937& rng) {
    if (!d.choices.empty()) return d.choices[std::uniform_int_distribution<size_t>(0, d.choices.size() - 1)(rng)];
    if (std::uniform_int_distribution<int>(0, 1)(rng) == 1) return d.defaultValue;
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", d.min);
    return text;
}

}  // namespace

bool ViewerSoak::advance(uint64_t frame, GLFWwindow* window, Settings& settings, std::string& technique, float& renderScale) {
    if (homeWidth_ == 0) {
        glfwGetWindowSize(window, &homeWidth_, &homeHeight_);
        homeTechnique_ = technique;
        homeRenderScale_ = renderScale;
    }
    if (iconifiedFor_ > 0 && --iconifiedFor_ == 0) glfwRestoreWindow(window);
    if (frame == lastFrame_) return false;  // act once per presented frame (the loop also spins while minimised)
    lastFrame_ = frame;
    if (warmup_.empty() && frame == 0)
        for (const SettingDecl& d : settingDecls())
            for (const std::string& choice : d.choices) warmup_.emplace_back(d.key, choice);
    if (frame < warmup_.size()) {  // warm-up: every choice once, with the home technique
        settings.set(warmup_[frame].first, warmup_[frame].second);
        return false;
    }
    const uint64_t phase = frame % kCycle;
    if (phase == kCycle - kHome) {  // home: the state every sample is taken in
        if (iconifiedFor_ > 0) glfwRestoreWindow(window), iconifiedFor_ = 0;
        glfwSetWindowSize(window, homeWidth_, homeHeight_);
        settings = Settings();
        technique = homeTechnique_;
        renderScale = homeRenderScale_;
    }
    if (phase >= kCycle - kHome) return phase == kCycle - 1;
    if (frame % 40 == 39) technique = nextTechnique(technique);
    if (frame % 5 == 4) {
        const auto& decls = settingDecls();
        const SettingDecl& d = decls[std::uniform_int_distribution<size_t>(0, decls.size() - 1)(rng_)];
        settings.set(d.key, randomValue(d, rng_));
    }
    if (frame % 61 == 60)  // the graph's images follow the frame's size, not the window's
        renderScale = kRenderScaleChoices[std::uniform_int_distribution<size_t>(0, kRenderScaleChoices.size() - 1)(rng_)];
    if (frame % 97 == 96) {  // from one pixel to 960x540
        const int w = std::uniform_int_distribution<int>(1, 960)(rng_), h = std::uniform_int_distribution<int>(1, 540)(rng_);
        glfwSetWindowSize(window, w, h);
    }
    if (frame % 251 == 250) {
        glfwIconifyWindow(window);
        iconifiedFor_ = 8;
    }
    return false;
}

}  // namespace ppr::app
