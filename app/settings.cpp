#include "settings.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ppr::app {

const std::vector<SettingSpec>& settingSpecs() {
    static const std::vector<SettingSpec> specs = {
        {"debug", "none", {"none", "albedo", "normals", "roughness", "reflectors", "depth", "intermediate", "holes", "tiles", "atlas"}, 0, 0,
         "debug view: G-buffer channels, reflector ids, PPR's decoded intermediate buffer, PPR's hole mask, "
         "reflectors surviving PPR's per-tile culling (heat map), PPR's glass reflection atlas"},
        {"holes", "1", {"0", "1"}, 0, 0, "PPR hole filling from the neighbour with the shortest offset"},
        {"filter", "1", {"0", "1"}, 0, 0, "PPR filtered (bilinear, encoded fractions) colour sample instead of point"},
        {"antibleed", "1", {"0", "1"}, 0, 0, "PPR colour-bleeding reduction (YCoCg, luma and chroma apart)"},
        {"tiles", "1", {"0", "1"}, 0, 0, "PPR per-tile reflector culling in the projection pass (0: every reflector per pixel)"},
        {"indirect", "1", {"0", "1"}, 0, 0, "PPR reflection pass dispatched indirectly over reflector tiles (0: whole screen)"},
        {"fallback", "ssr", {"ssr", "none"}, 0, 0,
         "PPR: reflective pixels no reflector rectangle covers (curved, rough) get ssr-hiz over the non-planar tiles, or nothing"},
        {"ssr_distance", "40", {}, 0.1, 1000.0, "SSR: longest reflected ray, metres (all four SSR techniques and PPR's fallback)"},
        {"ssr_thickness", "0.05", {}, 0.001, 100.0, "SSR: a surface is this many metres thick (plus ssr_thickness_scale x its distance)"},
        {"ssr_thickness_scale", "0.02", {}, 0.0, 1.0, "SSR: thickness added per metre of view distance"},
        {"ssr_steps", "4096", {}, 1, 65536, "SSR: most march iterations per ray (the default never cuts a ray short on screen)"},
        {"glass", "1", {"0", "1"}, 0, 0, "PPR reflections in glass panels, through the glass atlas (0: glass only transmits)"},
        {"glass_atlas", "1024", {}, 64, 8192, "texels per side of the glass atlas (PPR's intermediate buffer for glass panels)"},
        {"exposure", "1", {}, 0.01, 100.0, "exposure multiplier before tonemapping"},
        {"shadowres", "2048", {}, 256, 8192, "shadow map resolution (texels per side)"},
    };
    return specs;
}

namespace {
const SettingSpec* find(const std::string& key) {
    for (const SettingSpec& s : settingSpecs())
        if (s.key == key) return &s;
    return nullptr;
}
std::string knownKeys() {
    std::string out;
    for (const SettingSpec& s : settingSpecs()) out += (out.empty() ? "" : ", ") + s.key;
    return out;
}
}  // namespace

Settings::Settings() {
    for (const SettingSpec& s : settingSpecs()) values_[s.key] = s.defaultValue;
}

void Settings::apply(const std::string& assignment) {
    size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw std::runtime_error("--set " + assignment + ": expected key=value (known keys: " + knownKeys() + ")");
    set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

void Settings::set(const std::string& key, const std::string& value) {
    const SettingSpec* spec = find(key);
    if (!spec) throw std::runtime_error("--set " + key + ": unknown key (known keys: " + knownKeys() + ")");
    if (!spec->choices.empty()) {
        if (std::find(spec->choices.begin(), spec->choices.end(), value) == spec->choices.end()) {
            std::string list;
            for (const std::string& c : spec->choices) list += (list.empty() ? "" : "|") + c;
            throw std::runtime_error("--set " + key + "=" + value + ": expected one of " + list);
        }
    } else {
        size_t used = 0;
        double v = 0.0;
        try {
            v = std::stod(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != value.size() || !std::isfinite(v) || v < spec->min || v > spec->max)
            throw std::runtime_error("--set " + key + "=" + value + ": expected a number in [" + std::to_string(spec->min) + ", " +
                                     std::to_string(spec->max) + "]");
    }
    values_[key] = value;
}

const std::string& Settings::get(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end()) throw std::logic_error("setting '" + key + "' is not registered");
    return it->second;
}

double Settings::number(const std::string& key) const { return std::stod(get(key)); }

}  // namespace ppr::app
