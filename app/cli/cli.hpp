#pragma once
// Command line per the DESIGN.md contract (techniques and settings from their tables):
//   ppr [view|capture|compare|bench|fit] [--scene F] [--reflectors F] [--camera NAME|x,y,z,yaw,pitch[,fov]]
//       [--size WxH] [--technique T] [--set key=value]... [--frames N] [--path P] [--out DIR] [--validation]
#include "settings/settings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ppr::app {

enum class Mode { Auto, View, Capture, Compare, Bench, Fit };

struct Options {
    Mode mode = Mode::Auto;
    std::string scene;       // empty = built-in default scene
    std::string reflectors;  // empty = scene sidecar / glTF extras
    std::string camera;      // empty = every named camera (capture) / the first (view)
    std::string path;        // --path still|animate|strafe|dolly|orbit|FILE (capture, compare); empty = no path
    uint32_t width = 1280, height = 720;
    std::string technique = "ppr";        // capture / view: the last --technique given
    std::vector<std::string> techniques;  // compare: every --technique given, in order (default: ppr)
    std::string reference = "planar";     // compare: what techniques are scored against (a reference technique)
    std::vector<std::string> sets;  // validated "key=value" assignments, in order
    uint32_t frames = 0;            // 0 = mode default
    std::string out = "out";
    bool outGiven = false;  // fit: --out names the reflector file (default out/<scene stem>.reflectors.json)
    bool validation = false;
    bool dumpGraph = false;  // --dump-graph: write graph.dot next to the report
    bool help = false;
    // bench: which measurements (techniques, reflectors, coverage; empty = all) and frames left out
    // of the medians first.
    std::vector<std::string> sweeps;
    uint32_t warmup = 3;
    // bench: how many times each sweep is measured, every row once per round in turn; bench.json gives
    // the medians over the rounds and each round's values, bench.md the ratios within each round.
    uint32_t rounds = 1;
    // fit: which materials' flat regions become reflectors (app/fit/fit.hpp).
    std::optional<std::string> fitMaterials;  // --materials REGEX
    std::optional<float> fitMaxRoughness;     // --max-roughness R
    float fitMinArea = 0.05f;                 // --min-area A (m²)
    bool fitAppend = false;                   // --append: keep the reflectors already in the output file
    // view: the frame is rendered at this fraction of the window's size and upscaled into it
    // (app/render/render_scale.hpp); 1 = the window's own resolution. None (`auto`, the default):
    // the device's type decides (defaultRenderScale).
    std::optional<float> renderScale;
};

// A technique with its own settings: "ppr@normalmap=off,holes=0" (compare and bench rows, capture).
struct TechniqueVariant {
    std::string name;               // a technique of the table
    std::vector<std::string> sets;  // "key=value" applied over the --set values
};
// Throws std::runtime_error naming the technique or the setting that is wrong.
TechniqueVariant parseTechniqueVariant(const std::string& text);

// `ppr bench --sweep` names.
const std::vector<std::string>& benchSweepNames();

constexpr float kMinRenderScale = 0.1f;  // --render-scale's least value (a tenth of each side)
constexpr uint32_t kMinSize = 1;  // a 1-pixel-wide frame is valid (the validation sweep renders 1x4096)
constexpr uint32_t kMaxSize = 8192;
constexpr uint32_t kMaxFrames = 100000;
constexpr uint32_t kMaxRounds = 100;
constexpr uint32_t kDefaultPathFrames = 32;  // frames of a named --path without --frames

// Throws std::runtime_error with one line naming the option and the problem.
Options parseCommandLine(int argc, const char* const* argv);
// `text` with control characters as C escapes (\r, \t, \x01): a message quoting an argument stays one line.
std::string printable(const std::string& text);
std::string usage();

}  // namespace ppr::app
