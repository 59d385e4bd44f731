#include "techniques/technique_table.hpp"

#include "ssr_brute/ssr_brute_pass.hpp"
#include "ssr_hiz/ssr_hiz_pass.hpp"
#include "ssr_linear/ssr_linear_pass.hpp"
#include "ssr_lowq/ssr_lowq_pass.hpp"
#include "techniques/floor_technique.hpp"
#include "techniques/planar_technique.hpp"
#include "techniques/ppr_technique.hpp"
#include "techniques/raytraced_technique.hpp"
#include "techniques/ssr_technique.hpp"

#include <algorithm>
#include <stdexcept>

namespace ppr::app {
namespace {

template <class T>
std::unique_ptr<Technique> make(FrameServices& s) {
    return std::make_unique<T>(s);
}
template <std::unique_ptr<passes::SsrTracePass> (*Pass)(const vk::Context&), bool Hierarchy>
std::unique_ptr<Technique> makeSsr(FrameServices& s) {
    return std::make_unique<SsrTechnique>(s, Pass, Hierarchy);
}

}  // namespace

const std::vector<TechniqueDesc>& techniqueTable() {
    static const std::vector<TechniqueDesc> table = {
        {"ppr", "pixel-projected reflections (with ssr-hiz on curved and rough surfaces: --set fallback)", {"tiles.", "hiz."}, false,
         make<PprTechnique>},
        {"ssr-brute", "screen-space ray march through every pixel the ray crosses", {"tiles."}, false,
         makeSsr<passes::makeSsrBrutePass, false>},
        {"ssr-lowq", "screen-space ray march, 64 px stride + binary search", {"tiles."}, false, makeSsr<passes::makeSsrLowqPass, false>},
        {"ssr-hiz", "screen-space ray march over a min-depth hierarchy", {"tiles.", "hiz."}, false, makeSsr<passes::makeSsrHizPass, true>},
        {"ssr-linear", "screen-space ray march, linear steps + binary search (the SSR write-up's)", {"tiles."}, false,
         makeSsr<passes::makeSsrLinearPass, false>},
        {"planar", "ground truth: the scene re-rendered per reflector plane from the mirrored eye", {}, true, make<PlanarTechnique>},
        {"raytraced", "exact reference: mirror rays traced through the scene with VK_KHR_ray_query, hits lit as the lighting pass lights them",
         {}, true, make<RaytracedTechnique>},
        {"floor", "the cost floor of screen-space reflections (one read of depth and colour; draws no reflection)", {}, false,
         make<FloorTechnique>},
        {"none", "the lit scene without reflections", {}, false, nullptr},
    };
    return table;
}

const TechniqueDesc* findTechnique(const std::string& name) {
    for (const TechniqueDesc& t : techniqueTable())
        if (t.name == name) return &t;
    return nullptr;
}

std::vector<std::string> techniqueNames() {
    std::vector<std::string> names;
    for (const TechniqueDesc& t : techniqueTable()) names.push_back(t.name);
    return names;
}

const TechniqueDesc& techniqueDesc(const std::string& name) {
    if (const TechniqueDesc* t = findTechnique(name)) return *t;
    std::string list;
    for (const std::string& n : techniqueNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::runtime_error("unknown technique '" + name + "' (available: " + list + ")");
}

bool isTechnique(const std::string& name) { return findTechnique(name) != nullptr; }

bool isSsrTechnique(const std::string& name) { return name.rfind("ssr-", 0) == 0 && isTechnique(name); }

bool isTechniquePass(const std::string& technique, const std::string& pass) {
    const TechniqueDesc* t = findTechnique(technique);
    if (!t || !t->make) return false;
    auto startsWith = [&](const std::string& prefix) { return pass.compare(0, prefix.size(), prefix) == 0; };
    if (pass == technique || startsWith(technique + ".")) return true;
    return std::any_of(t->sharedCost.begin(), t->sharedCost.end(), startsWith);
}

double techniqueCost(const std::string& technique, const std::map<std::string, double>& passMs) {
    double sum = 0.0;
    for (const auto& [pass, ms] : passMs)
        if (isTechniquePass(technique, pass)) sum += ms;
    return sum;
}

std::string techniquesUsage() {
    std::string out;
    for (const TechniqueDesc& t : techniqueTable()) {
        std::string name = t.name;
        name.resize(std::max<size_t>(name.size(), 12), ' ');
        out += "    " + name + t.help + (t.name == "ppr" ? " (default)" : "") + "\n";
    }
    return out;
}

}  // namespace ppr::app
