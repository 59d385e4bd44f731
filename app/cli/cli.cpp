#include "cli/cli.hpp"

#include "ppr_common/encoding.h"
#include "techniques/technique_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ppr::app {
namespace {

uint32_t parseUnsigned(const std::string& option, const std::string& text, uint32_t lo, uint32_t hi) {
    size_t used = 0;
    unsigned long v = 0;
    try {
        if (text.empty() || text[0] == '-' || text[0] == '+') throw std::invalid_argument("sign");
        v = std::stoul(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || used == 0) throw std::runtime_error(option + " " + text + ": expected a whole number");
    if (v < lo || v > hi)
        throw std::runtime_error(option + " " + text + ": out of range (" + std::to_string(lo) + ".." + std::to_string(hi) + ")");
    return static_cast<uint32_t>(v);
}

float parseFloat(const std::string& option, const std::string& text, float lo, float hi) {
    size_t used = 0;
    float v = 0.0f;
    try {
        v = std::stof(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || used == 0 || !std::isfinite(v)) throw std::runtime_error(option + " " + text + ": expected a number");
    if (v < lo || v > hi) {
        char range[64];
        std::snprintf(range, sizeof(range), "%g..%g", double(lo), double(hi));
        throw std::runtime_error(option + " " + text + ": out of range (" + range + ")");
    }
    return v;
}

}  // namespace

const std::vector<std::string>& benchSweepNames() {
    static const std::vector<std::string> names = {"techniques", "reflectors", "coverage"};
    return names;
}

TechniqueVariant parseTechniqueVariant(const std::string& text) {
    TechniqueVariant v;
    const size_t at = text.find('@');
    v.name = text.substr(0, at);
    if (!isTechnique(v.name)) {
        std::string list;
        for (const std::string& s : techniqueNames()) list += (list.empty() ? "" : ", ") + s;
        throw std::runtime_error("--technique " + text + ": '" + v.name + "' is not available in this build (available: " + list + ")");
    }
    if (at == std::string::npos) return v;
    Settings check;
    size_t start = at + 1;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string kv = text.substr(start, comma - start);
        try {
            check.apply(kv);
        } catch (const std::exception& e) {
            throw std::runtime_error("--technique " + text + ": " + e.what());
        }
        v.sets.push_back(kv);
        start = comma + 1;
    }
    return v;
}

static std::string referenceNames() {
    std::string list;
    for (const TechniqueDesc& t : techniqueTable())
        if (t.reference) list += (list.empty() ? "" : "|") + t.name;
    return list;
}

std::string usage() {
    return "usage: ppr [view|capture|compare|bench|fit] [options]\n"
           "  view                 interactive window (default when a display is present)\n"
           "  capture              render headless, write final.png + report.json (default without a display)\n"
           "  compare              render techniques and the planar ground truth; write contact.png + metrics.json\n"
           "  bench                time the techniques on one camera (default: all but none; planar is the reference),\n"
           "                       against PPR and the floor, and PPR's scaling sweeps; write bench.json, bench.md, bench.png\n"
           "  fit                  fit reflector rectangles to the scene's flat surfaces of the selected materials; print\n"
           "                       them and write a reflector file (--out FILE, default out/<scene>.reflectors.json)\n"
           "    --materials REGEX  fit: materials whose name matches (ECMAScript, searched)\n"
           "    --max-roughness R  fit: materials with roughness factor <= R (with --materials: both must hold;\n"
           "                       neither: the materials marked reflective, extras \"ppr_reflective\")\n"
           "    --min-area A       fit: drop flat regions under A square metres (default 0.05)\n"
           "    --append           fit: keep the reflectors already in the output file and add these after them\n"
           "                       (e.g. floors at one --min-area, then glazing at another)\n"
           "options:\n"
           "  --scene FILE         .gltf or .glb, or stress:N (N = 1..4096 mirror tiles; default: the built-in default scene)\n"
           "  --reflectors FILE    reflector JSON (default: <scene>.reflectors.json or glTF node extras)\n"
           "  --camera NAME|x,y,z,yawDeg,pitchDeg[,fovYDeg]\n"
           "                       capture: default = every named camera; view: the first one\n"
           "  --size WxH           default 1280x720 (1..8192 per side; ppr: at most " + std::to_string(gpu::kPprMaxExtent) +
           ", its offsets are 12-bit)\n"
           "  --technique T[@key=value,...]   compare and bench: repeatable; T one of the list below, with its own\n"
           "                       settings after @ (e.g. ppr@normalmap=off, a row of its own)\n" +
           techniquesUsage() +
           "  --reference R        compare: what the techniques are scored against, one of " + referenceNames() +
           " (default planar)\n"
           "  --set key=value      repeatable; keys (declared once: app/settings/settings.cpp):\n" + settingsUsage() +
           "  --path P             capture, compare: render a camera path from the camera, one frame per pose, each frame\n"
           "                       read back: still | animate (still camera, the scene's animation playing) | strafe | dolly |\n"
           "                       orbit (--frames poses, default " + std::to_string(kDefaultPathFrames) + ") or a FILE with\n"
           "                       one x,y,z,yawDeg,pitchDeg[,fovYDeg] per line; compare scores every frame against the\n"
           "                       reference supersampled 16 times (metrics.json \"temporal\"; docs/temporal.md)\n"
           "  --frames N           frames to render (capture default 5: median GPU times over them; bench default 10)\n"
           "  --warmup N           bench: frames rendered before measuring (default 3)\n"
           "  --sweep S            bench, repeatable: techniques | reflectors | coverage (default: all three)\n"
           "  --rounds N           bench: measure every row N times in turn (default 1); bench.json gives the medians and\n"
           "                       each round's values, bench.md the ratios within each round (for a noisy machine)\n"
           "  --render-scale S     view: render at S times the window's size (0.1..1) and upscale, for interactive\n"
           "                       frame rates on a CPU device; also in the panel. auto (default): 1 on a GPU, 0.5\n"
           "                       on a CPU device such as lavapipe\n"
           "  --out DIR            output directory (default out)\n"
           "  --validation         Khronos validation + synchronization validation; any error exits 1\n"
           "                       (also enabled by PPR_VALIDATION=1)\n"
           "  --dump-graph         write graph.dot (Graphviz) of the frame graph next to the report\n";
}

static Options parseArguments(int argc, const char* const* argv) {
    Options o;
    Settings check;  // validates --set values as they are parsed
    int i = 1;
    if (i < argc && argv[i][0] != '-') {
        std::string m = argv[i++];
        if (m == "view") o.mode = Mode::View;
        else if (m == "capture") o.mode = Mode::Capture;
        else if (m == "compare") o.mode = Mode::Compare;
        else if (m == "bench") o.mode = Mode::Bench;
        else if (m == "fit") o.mode = Mode::Fit;
        else throw std::runtime_error("unknown command '" + m + "' (expected view, capture, compare, bench or fit)");
    }
    auto value = [&](const std::string& opt) -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(opt + ": missing value");
        return argv[++i];
    };
    for (; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--help" || a == "-h") o.help = true;
        else if (a == "--scene") o.scene = value(a);
        else if (a == "--reflectors") o.reflectors = value(a);
        else if (a == "--camera") o.camera = value(a);
        else if (a == "--path") {
            o.path = value(a);
            if (o.path.empty()) throw std::runtime_error("--path: expected still, animate, strafe, dolly, orbit or a file");
        }
        else if (a == "--out") {
            o.out = value(a);
            o.outGiven = true;
        }
        else if (a == "--materials") o.fitMaterials = value(a);
        else if (a == "--max-roughness") o.fitMaxRoughness = parseFloat(a, value(a), 0.0f, 1.0f);
        else if (a == "--min-area") o.fitMinArea = parseFloat(a, value(a), 0.0f, 1e10f);
        else if (a == "--append") o.fitAppend = true;
        else if (a == "--validation") o.validation = true;
        else if (a == "--dump-graph") o.dumpGraph = true;
        else if (a == "--frames") o.frames = parseUnsigned(a, value(a), 1, kMaxFrames);
        else if (a == "--warmup") o.warmup = parseUnsigned(a, value(a), 0, kMaxFrames);
        else if (a == "--rounds") o.rounds = parseUnsigned(a, value(a), 1, kMaxRounds);
        else if (a == "--render-scale") {
            const std::string scale = value(a);
            o.renderScale = scale == "auto" ? std::nullopt : std::optional<float>(parseFloat(a, scale, kMinRenderScale, 1.0f));
        }
        else if (a == "--sweep") {
            const std::string sweep = value(a);
            const auto& names = benchSweepNames();
            if (std::find(names.begin(), names.end(), sweep) == names.end())
                throw std::runtime_error("--sweep " + sweep + ": expected techniques, reflectors or coverage");
            o.sweeps.push_back(sweep);
        }
        else if (a == "--reference") {
            o.reference = value(a);
            const TechniqueDesc* t = findTechnique(o.reference);
            if (!t || !t->reference) {
                std::string list;
                for (const TechniqueDesc& r : techniqueTable())
                    if (r.reference) list += (list.empty() ? "" : ", ") + r.name;
                throw std::runtime_error("--reference " + o.reference + ": not a reference technique (available: " + list + ")");
            }
        }
        else if (a == "--technique") {
            o.technique = value(a);
            parseTechniqueVariant(o.technique);  // validates the name and any @key=value overrides
            o.techniques.push_back(o.technique);
        } else if (a == "--size") {
            std::string s = value(a);
            size_t x = s.find('x');
            if (x == std::string::npos) throw std::runtime_error("--size " + s + ": expected WxH, e.g. 1280x720");
            o.width = parseUnsigned("--size", s.substr(0, x), kMinSize, kMaxSize);
            o.height = parseUnsigned("--size", s.substr(x + 1), kMinSize, kMaxSize);
        } else if (a == "--set") {
            std::string kv = value(a);
            check.apply(kv);
            o.sets.push_back(kv);
        } else {
            throw std::runtime_error("unknown option '" + a + "' (see ppr --help)");
        }
    }
    if (o.mode != Mode::Fit && (o.fitMaterials || o.fitMaxRoughness || o.fitMinArea != Options{}.fitMinArea || o.fitAppend))
        throw std::runtime_error("--materials, --max-roughness, --min-area and --append belong to ppr fit");
    if (o.mode == Mode::Fit && o.outGiven && o.out.empty()) throw std::runtime_error("--out: expected a file name");
    if (!o.path.empty() && o.mode != Mode::Capture && o.mode != Mode::Compare)
        throw std::runtime_error("--path " + o.path + ": only capture and compare render camera paths");
    if (o.mode != Mode::View && o.mode != Mode::Auto && o.renderScale && *o.renderScale != 1.0f)
        throw std::runtime_error("--render-scale: only the viewer renders below its window's size (capture, compare and bench render at --size)");
    if (o.mode != Mode::Bench && o.rounds != 1) throw std::runtime_error("--rounds " + std::to_string(o.rounds) + ": only bench measures in rounds");
    if (o.mode == Mode::Bench && o.sweeps.empty()) o.sweeps = benchSweepNames();
    if (o.mode == Mode::Compare && o.techniques.empty()) o.techniques = {"ppr"};
    auto listsPpr = [&] {
        return std::any_of(o.techniques.begin(), o.techniques.end(), [](const std::string& t) { return parseTechniqueVariant(t).name == "ppr"; });
    };
    bool usesPpr = parseTechniqueVariant(o.technique).name == "ppr";
    if (o.mode == Mode::Compare) usesPpr = listsPpr();
    // bench: the reflector and coverage sweeps always run PPR; the techniques sweep runs all by default.
    if (o.mode == Mode::Bench) usesPpr = o.techniques.empty() || listsPpr() || o.sweeps != std::vector<std::string>{"techniques"};
    if (usesPpr && std::max(o.width, o.height) > gpu::kPprMaxExtent)
        throw std::runtime_error("--size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                                 ": PPR encodes offsets with 12-bit integer parts, so it runs at most " + std::to_string(gpu::kPprMaxExtent) +
                                 " px per side (use --technique planar or none for larger sizes)");
    return o;
}

std::string printable(const std::string& text) {
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20 || u == 0x7f) out += std::string("\\x") + hex[u >> 4] + hex[u & 15];
        else out += c;
    }
    return out;
}

// Every message quotes the offending argument: control characters in it (found by fuzz_cli; a script
// saved with CRLF line ends passes "640x360\r") must not break the one-line error.
Options parseCommandLine(int argc, const char* const* argv) {
    try {
        return parseArguments(argc, argv);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(printable(e.what()));
    }
}

}  // namespace ppr::app
