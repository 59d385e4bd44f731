#include "settings/settings.hpp"

#include "common/frame.h"
#include "hiz/hiz_threads.hpp"
#include "ppr_project/project_threads.hpp"
#include "ppr_reach/reach_threads.hpp"
#include "taa/taa_threads.hpp"
#include "tile_classify/classify_threads.hpp"
#include "settings/debug_views.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <span>
#include <stdexcept>

namespace ppr::app {
namespace {

// A typed field of FrameSettings, as a captureless accessor (const access goes through const_cast).
template <class T>
using Field = T& (*)(FrameSettings&);

template <class T>
T& at(Field<T> field, const FrameSettings& s) {
    return field(const_cast<FrameSettings&>(s));
}

// Shortest round-trip text: 0.05 stays "0.05", 4096 stays "4096" (float fields print as floats).
template <class T>
std::string shortest(T v) {
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

SettingDecl toggle(std::string key, std::string owner, Field<bool> field, bool def, std::string help) {
    SettingDecl d{std::move(key), SettingKind::Toggle, def ? "1" : "0", {"0", "1"}, 0, 0, std::move(owner), std::move(help)};
    d.write = [field](FrameSettings& s, const std::string& v) { field(s) = v == "1"; };
    d.read = [field](const FrameSettings& s) { return std::string(at(field, s) ? "1" : "0"); };
    return d;
}

SettingDecl number(std::string key, std::string owner, Field<float> field, double def, double min, double max, std::string help) {
    SettingDecl d{std::move(key), SettingKind::Number, shortest(def), {}, min, max, std::move(owner), std::move(help)};
    d.write = [field](FrameSettings& s, const std::string& v) { field(s) = static_cast<float>(std::stod(v)); };
    d.read = [field](const FrameSettings& s) { return shortest(at(field, s)); };
    return d;
}

SettingDecl integer(std::string key, std::string owner, Field<uint32_t> field, uint32_t def, uint32_t min, uint32_t max, std::string help) {
    SettingDecl d{std::move(key), SettingKind::Integer, std::to_string(def), {}, double(min), double(max), std::move(owner), std::move(help)};
    d.write = [field](FrameSettings& s, const std::string& v) { field(s) = static_cast<uint32_t>(std::stod(v)); };
    d.read = [field](const FrameSettings& s) { return std::to_string(at(field, s)); };
    return d;
}

// A choice stored as an enum (or index) whose values are the positions in `names`.
template <class E>
SettingDecl choice(std::string key, std::string owner, Field<E> field, std::vector<std::string> names, std::string def, std::string help) {
    SettingDecl d{std::move(key), SettingKind::Choice, std::move(def), names, 0, 0, std::move(owner), std::move(help)};
    d.write = [field, names](FrameSettings& s, const std::string& v) {
        field(s) = static_cast<E>(std::find(names.begin(), names.end(), v) - names.begin());
    };
    d.read = [field, names](const FrameSettings& s) { return names.at(static_cast<size_t>(at(field, s))); };
    return d;
}

// debug: the names come from the debug-view table, the stored value is the shaders' constant.
SettingDecl debugSetting() {
    std::vector<std::string> names, help;
    for (const DebugViewDecl& v : debugViews()) {
        names.push_back(v.name);
        help.push_back(v.help + " (" + v.owner + ")");
    }
    SettingDecl d{"debug", SettingKind::Choice, "none", names, 0, 0, "frame", "debug view drawn over the frame"};
    d.choiceHelp = help;
    d.write = [](FrameSettings& s, const std::string& v) {
        for (const DebugViewDecl& view : debugViews())
            if (view.name == v) s.view.debug = view.value;
    };
    d.read = [](const FrameSettings& s) { return debugView(s.view.debug).name; };
    return d;
}

// A workgroup width: "auto" (stored as 0: the pass picks by device type) or one of the widths the
// pass offers, listed there once.
SettingDecl widthSetting(std::string key, std::string owner, Field<uint32_t> field, std::span<const uint32_t> offered, std::string help) {
    std::vector<std::string> names{"auto"};
    for (uint32_t t : offered) names.push_back(std::to_string(t));
    SettingDecl d{std::move(key), SettingKind::Choice, "auto", names, 0, 0, std::move(owner), std::move(help)};
    d.write = [field](FrameSettings& s, const std::string& v) { field(s) = v == "auto" ? 0u : static_cast<uint32_t>(std::stoul(v)); };
    d.read = [field](const FrameSettings& s) { return at(field, s) == 0 ? std::string("auto") : std::to_string(at(field, s)); };
    return d;
}

std::string join(const std::vector<std::string>& items, const char* sep) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : sep) + s;
    return out;
}

std::string knownKeys() {
    std::vector<std::string> keys;
    for (const SettingDecl& d : settingDecls()) keys.push_back(d.key);
    return join(keys, ", ");
}

// Throws naming the key, the value and what is accepted.
void validate(const SettingDecl& d, const std::string& value) {
    if (!d.choices.empty()) {
        if (std::find(d.choices.begin(), d.choices.end(), value) == d.choices.end())
            throw std::runtime_error("--set " + d.key + "=" + value + ": expected one of " + join(d.choices, "|"));
        return;
    }
    size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(value, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    const bool whole = d.kind != SettingKind::Integer || v == std::floor(v);
    if (used == 0 || used != value.size() || !std::isfinite(v) || v < d.min || v > d.max || !whole)
        throw std::runtime_error("--set " + d.key + "=" + value + ": expected " + (d.kind == SettingKind::Integer ? "a whole number" : "a number") +
                                 " in [" + shortest(d.min) + ", " + shortest(d.max) + "]");
}

}  // namespace

const std::vector<SettingDecl>& settingDecls() {
    static const std::vector<SettingDecl> decls = {
        debugSetting(),
        choice<HoleRule>("holes", "ppr", [](FrameSettings& s) -> HoleRule& { return s.ppr.holes; }, {"0", "1", "slides"}, "1",
                         "PPR hole filling: 0 none; 1 a pixel takes a neighbour's data only where the nearer layer encloses it "
                         "(or it has none); slides: the slides' rule (the neighbour with the shortest offset, 4 neighbours)"),
        toggle("facing", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.facing; }, true,
               "PPR projects only surfaces that face the mirrored eye (one seen from behind is hidden in the reflection by its "
               "object's front; 0: every surface, as the slides)"),
        toggle("splat", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.splat; }, true,
               "PPR: a surface the reflection magnifies (seen at a grazing angle, reflected face on) also writes the pixels "
               "between its pixels' landings, so what lies behind it does not show through (0: one pixel each, as the slides)"),
        toggle("filter", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.filter; }, true,
               "PPR filtered (bilinear, encoded fractions) colour sample instead of point"),
        toggle("antibleed", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.antibleed; }, true,
               "PPR colour-bleeding reduction (YCoCg, luma and chroma apart)"),
        toggle("tiles", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.tiles; }, true,
               "PPR per-tile reflector culling in the projection pass (0: every reflector per pixel)"),
        widthSetting("project_threads", "ppr", [](FrameSettings& s) -> uint32_t& { return s.ppr.projectThreads; }, passes::kProjectThreadChoices,
                     "PPR projection pass: invocations per 16x16 tile (auto: 32 on a CPU device, where barriers cost per "
                     "invocation; 256 on a GPU); the same images with any"),
        widthSetting("reach_threads", "ppr", [](FrameSettings& s) -> uint32_t& { return s.ppr.reachThreads; }, passes::kReachThreadChoices,
                     "PPR reach pass (with tiles=1 indirect=1: the tiles the projection runs on): invocations per 16x16 tile "
                     "(auto: 1 on a CPU device, 16 on a GPU); the same tiles with any"),
        toggle("indirect", "tiles", [](FrameSettings& s) -> bool& { return s.tiles.indirect; }, true,
               "PPR's reflection pass and the SSR techniques dispatched indirectly over the tile lists (0: whole screen)"),
        widthSetting("classify_threads", "tiles", [](FrameSettings& s) -> uint32_t& { return s.tiles.classifyThreads; },
                     passes::kClassifyThreadChoices,
                     "tile classification: invocations per 16x16 tile (auto: 1 on a CPU device, 64 on a GPU); the same "
                     "tile classes with any"),
        choice<PprFallback>("fallback", "ppr", [](FrameSettings& s) -> PprFallback& { return s.ppr.fallback; }, {"ssr", "none", "ssr_holes"},
                            "ssr_holes",
                            "PPR: reflective pixels no reflector rectangle covers (curved, rough) get ssr-hiz over the non-planar tiles, or "
                            "nothing; ssr_holes: also PPR's holes on normal-mapped reflectors (pixels nothing was projected to, where "
                            "the mapped ray finds what the flat reflection cannot: ppr.fallback.holes over the planar tiles that hold one)"),
        choice<NormalMap>("normalmap", "ppr, ssr, raytraced", [](FrameSettings& s) -> NormalMap& { return s.ppr.normalMap; }, {"off", "approx", "raymarch"},
                          "raymarch",
                          "normal-mapped reflectors: off (flat mirrors); PPR: approx (reflect about the mapped normal at the flat "
                          "reflection distance), raymarch (4 depth-tested taps along that ray, else flat); SSR and raytraced "
                          "reflect about the mapped normal unless off"),
        choice<NormalRefine>("normal_refine", "ppr", [](FrameSettings& s) -> NormalRefine& { return s.ppr.normalRefine; }, {"0", "1", "walk"}, "1",
                             "normalmap=raymarch: find where the ray meets what it reflects. 1: where it crosses the plane (from the "
                             "depth buffer) of the surface the flat reflection sees (then of the one seen there), if the depth buffer "
                             "shows that plane there, else the taps; walk: walk on past an approximated point that is not hidden and "
                             "bisect after a hidden tap (the search before 1, slower); 0: the slides' 4 taps alone"),
        toggle("contact", "ppr", [](FrameSettings& s) -> bool& { return s.ppr.contact; }, true,
               "holes=1: 4 depth-tested taps (2, 4, 8, 16 px) from each reflector pixel toward the point it reflects find "
               "what the main view hides in between, such as the underside of an object standing on the reflector; not on "
               "normal-mapped pixels with normalmap=approx|raymarch (but normal_refine=walk), which follow the mapped ray "
               "(0: off)"),
        choice<RtCoverage>("rt_coverage", "raytraced", [](FrameSettings& s) -> RtCoverage& { return s.raytrace.coverage; }, {"exact", "raster"},
                           "exact",
                           "ray-traced reference with normalmap=off, and its glass atlas: at silhouettes the triangle the ray meets "
                           "(exact), or the one the planar reference's rasterizer shows there, its vertices snapped to the device's "
                           "sub-pixel grid (raster: 9 rays a pixel, 25 near an edge; proves the two references agree, docs/raytraced.md)"),
        toggle("fallback_env", "env", [](FrameSettings& s) -> bool& { return s.env.fallback; }, false,
               "reflections that leave the screen or find nothing show the environment (env_source), blended in near the screen edges (0: black)"),
        choice<EnvSource>("env_source", "env", [](FrameSettings& s) -> EnvSource& { return s.env.source; }, {"sky", "probe"}, "probe",
                          "what fallback_env=1 shows: the sky along the reflected ray, or the reflection probe (a cubemap of the lit "
                          "scene rendered once, box-projected; the sky where it sees sky)"),
        number("ssr_distance", "ssr", [](FrameSettings& s) -> float& { return s.ssr.distance; }, 40, 0.1, 1000.0,
               "SSR: longest reflected ray, metres (all four SSR techniques and PPR's fallback)"),
        number("ssr_thickness", "ssr", [](FrameSettings& s) -> float& { return s.ssr.thickness; }, 0.05, 0.001, 100.0,
               "SSR: a surface is this many metres thick (plus ssr_thickness_scale x its distance)"),
        number("ssr_thickness_scale", "ssr", [](FrameSettings& s) -> float& { return s.ssr.thicknessScale; }, 0.02, 0.0, 1.0,
               "SSR: thickness added per metre of view distance"),
        integer("ssr_steps", "ssr", [](FrameSettings& s) -> uint32_t& { return s.ssr.steps; }, 4096, 1, 65536,
                "SSR: most march iterations per ray (the default never cuts a ray short on screen)"),
        toggle("hiz_skip", "ssr", [](FrameSettings& s) -> bool& { return s.ssr.hizSkip; }, true,
               "ssr-hiz and PPR's fallback: where the ray walks behind an object pixel by pixel, cross an 8x8 cell whose "
               "farthest surface it stays behind (by more than the thickness) in one step; the same reflections (0: walk)"),
        widthSetting("hiz_threads", "ssr", [](FrameSettings& s) -> uint32_t& { return s.ssr.hizThreads; }, passes::kHizThreadChoices,
                     "depth hierarchy build (ssr-hiz, PPR's fallback): invocations per 64x64 cell, one dispatch for every level "
                     "(auto: 16 on a CPU device, 256 on a GPU); the same hierarchy with any"),
        toggle("glass", "glass", [](FrameSettings& s) -> bool& { return s.glass.enabled; }, true,
               "PPR reflections in glass panels, through the glass atlas (0: glass only transmits)"),
        integer("glass_atlas", "glass", [](FrameSettings& s) -> uint32_t& { return s.glass.atlas; }, 1024, 64, 8192,
                "texels per side of the glass atlas (PPR's intermediate buffer for glass panels)"),
        toggle("taa", "taa", [](FrameSettings& s) -> bool& { return s.taa.enabled; }, false,
               "temporal anti-aliasing: Halton (2, 3) jitter of 16 samples, history reprojected by depth and the previous "
               "view-projection (and a moving object's own motion), YCoCg variance clipping, Catmull-Rom history sample (0: off, bit-identical frames)"),
        choice<Reproject>("reproject", "taa", [](FrameSettings& s) -> Reproject& { return s.taa.reproject; }, {"surface", "candidates", "virtual"},
                          "virtual",
                          "taa=1: the reflection's own history, fetched by the surface's motion (a plain TAA), the smallest of the "
                          "surface's and the reflected point's motion with their parallax-scaled forms (candidates), or the virtual "
                          "point's motion with disocclusion rejected by its depth (virtual; every technique gives path lengths: "
                          "pixels without one, misses, fall back to the surface's motion)"),
        toggle("taa_split", "taa", [](FrameSettings& s) -> bool& { return s.taa.split; }, true,
               "taa=1: the frame's history holds the surface part alone and the reflection's own resolved history is "
               "added after, so the frame's TAA never drags a reflection with the surface (0: the frame's history holds the "
               "whole colour; with reproject=virtual reflector pixels mix in a fetch at the reflection's motion)"),
        toggle("taa_average", "taa", [](FrameSettings& s) -> bool& { return s.taa.average; }, true,
               "taa=1: each history pixel counts its frames: the first 32 after a cut or a disocclusion get equal shares, "
               "and a still pixel (history at a texel centre, inside a 2.5-sigma box) averages the 16-frame jitter cycle and "
               "keeps it until the box moves, so a still view stops flickering (0: the luma-driven feedback of 0.88-0.97 "
               "alone; switching it on restarts the histories)"),
        toggle("taa_motion_cap", "taa", [](FrameSettings& s) -> bool& { return s.taa.motionCap; }, true,
               "taa=1, taa_average=1: the frame's history keeps at most 0.7 of itself wherever it was fetched between texels "
               "(ramping back to 1 within a tenth of a texel of a centre), so a moving view does not soften a little more with "
               "every frame's Catmull-Rom fetch (a still view is unchanged; 0: the feedback alone)"),
        toggle("taa_reflection_cap", "taa", [](FrameSettings& s) -> bool& { return s.taa.reflectionCap; }, false,
               "taa=1, taa_average=1: the motion cap on the reflection's own history too (taa.reflection): sharper "
               "reflections under motion for every reproject mode, and the most for surface, whose misplaced history it also "
               "drops sooner (a still view is unchanged; 0: the reflection's history keeps the feedback alone)"),
        toggle("taa_rim_keep", "taa", [](FrameSettings& s) -> bool& { return s.taa.rimKeep; }, true,
               "taa=1, taa_average=1: a pixel that the jitter takes off a reflector's rim while the view moves keeps its "
               "reflection's history (fetched where its surface was, from the texels there that held one) for the frames "
               "that bring the reflection back, as a still pixel does (0: only a still pixel keeps it)"),
        toggle("taa_still_spread", "taa", [](FrameSettings& s) -> bool& { return s.taa.stillSpread; }, true,
               "taa=1, taa_average=1: a still pixel whose run holds 4 frames or more keeps its history unclipped while the "
               "frame's luma lies within 2.5 standard deviations of the luma its own run has shown, so an edge the jitter "
               "cycle straddles stops restarting its average (0: the 3x3 neighbourhood's box alone decides)"),
        toggle("taa_still_range", "taa", [](FrameSettings& s) -> bool& { return s.taa.stillRange; }, true,
               "taa=1, taa_still_spread=1: the spread is the luma range the run has shown, from its first frame on, so a line "
               "thinner than a pixel, which most of the jitter cycle misses, keeps its average too (0: within 2.5 standard "
               "deviations of the run's mean, from its fourth frame; switching restarts the histories)"),
        toggle("taa_still_keep", "taa", [](FrameSettings& s) -> bool& { return s.taa.stillKeep; }, true,
               "taa=1, taa_average=1, reproject=virtual: a still pixel's reflection history is kept whatever depth its reflected "
               "path has this frame, unless a moving object is reflected there or beside: on a reflector's rim the jitter alone "
               "changes what the pixel reflects, and every phase is its history (0: a path depth outside the neighbourhood's "
               "rejects the history)"),
        toggle("taa_moving_edge", "taa", [](FrameSettings& s) -> bool& { return s.taa.movingEdge; }, true,
               "taa=1, reproject=virtual: beside a moving object's reflection, a pixel whose reflection history its path's depth "
               "rejects, though its neighbours' paths span that depth, and which moved less than a pixel, restarts from the "
               "neighbourhood's mean: the jitter flips it across the object's reflected edge, and one sample a frame "
               "flickers (0: from its own jittered sample)"),
        toggle("taa_moving_filter", "taa", [](FrameSettings& s) -> bool& { return s.taa.movingFilter; }, true,
               "taa=1: on and beside a moving object, the frame's TAA blends the current frame reconstructed at the pixel's "
               "centre from its 3x3 jittered samples (a narrow Gaussian), not the one sample the jitter put there: an edge "
               "the jitter moves across flickers less (0: the jittered sample)"),
        widthSetting("taa_threads", "taa", [](FrameSettings& s) -> uint32_t& { return s.taa.threads; }, passes::kTaaThreadChoices,
                     "taa=1: invocations per 16x16 tile in both resolves, each a column of 256/threads pixels (auto: 16 on a CPU "
                     "device, where a workgroup costs per invocation; 256 on a GPU); the same images with any"),
        number("exposure", "frame", [](FrameSettings& s) -> float& { return s.view.exposure; }, 1, 0.01, 100.0, "exposure multiplier before tonemapping"),
        integer("shadowres", "frame", [](FrameSettings& s) -> uint32_t& { return s.view.shadowRes; }, 2048, 256, 8192,
                "shadow map resolution (texels per side)"),
        toggle("shadow_cache", "frame", [](FrameSettings& s) -> bool& { return s.view.shadowCache; }, true,
               "the sun's shadow map is kept from frame to frame: the casters the animation never moves are drawn once "
               "(again when shadowres changes), and an animated scene's moving casters over a copy of them when its pose "
               "changes (shadow.restore, shadow.moving); the same images either way (0: the whole map drawn every frame)"),
        choice<ClearMethod>("clear", "frame", [](FrameSettings& s) -> ClearMethod& { return s.view.clear; }, {"auto", "transfer", "compute"},
                            "auto",
                            "how passes clear images: vkCmdClearColorImage (transfer; a memset on lavapipe), a compute pass (on an "
                            "H100 0.008 ms against the transfer clear's 0.32 for a 1080p rgba16f image), or auto (compute unless "
                            "the device is a CPU); the same bits either way"),
        choice<DepthPrepass>("depth_prepass", "frame", [](FrameSettings& s) -> DepthPrepass& { return s.view.depthPrepass; },
                             {"0", "1", "auto"}, "auto",
                             "the G-buffer draws the opaque scene's depth alone first, so its fragment shader runs once per "
                             "visible pixel (gbuffer.prepass; masked materials keep their alpha test in the G-buffer pass); the "
                             "same images either way (0: one pass, shading every layer drawn; auto: the pre-pass while the "
                             "opaque triangles number at most a quarter of the frame's pixels, beyond which it cost more than "
                             "it saved on lavapipe)"),
    };
    return decls;
}

const SettingDecl* findSetting(const std::string& key) {
    for (const SettingDecl& d : settingDecls())
        if (d.key == key) return &d;
    return nullptr;
}

std::string settingsUsage() {
    std::string out;
    for (const SettingDecl& d : settingDecls()) {
        const std::string values = d.choices.empty() ? "[" + shortest(d.min) + ", " + shortest(d.max) + "]" : join(d.choices, "|");
        out += "    " + d.key + "=" + values + " (default " + d.defaultValue + "; " + d.owner + ")\n        " + d.help + "\n";
        for (size_t i = 0; i < d.choiceHelp.size(); ++i) out += "          " + d.choices[i] + ": " + d.choiceHelp[i] + "\n";
    }
    return out;
}

Settings::Settings() {
    for (const SettingDecl& d : settingDecls()) d.write(values_, d.defaultValue);
}

void Settings::apply(const std::string& assignment) {
    const size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw std::runtime_error("--set " + assignment + ": expected key=value (known keys: " + knownKeys() + ")");
    set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

void Settings::set(const std::string& key, const std::string& value) {
    const SettingDecl* d = findSetting(key);
    if (!d) throw std::runtime_error("--set " + key + ": unknown key (known keys: " + knownKeys() + ")");
    validate(*d, value);
    d->write(values_, value);
}

std::string Settings::get(const std::string& key) const {
    const SettingDecl* d = findSetting(key);
    if (!d) throw std::logic_error("setting '" + key + "' is not declared");
    return d->read(values_);
}

double Settings::number(const std::string& key) const { return std::stod(get(key)); }

std::map<std::string, std::string> Settings::canonicalTexts() const {
    std::map<std::string, std::string> out;
    for (const SettingDecl& d : settingDecls()) out[d.key] = d.read(values_);
    return out;
}

}  // namespace ppr::app
