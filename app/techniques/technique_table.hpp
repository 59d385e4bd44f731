#pragma once
// The one list of techniques. The CLI (--technique and --help), the viewer's selector and F3,
// compare, bench, timing attribution and the renderer all read this table; adding a technique is a
// module in this folder plus one row in technique_table.cpp.
#include "frame/technique.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ppr::app {

struct TechniqueDesc {
    std::string name;
    std::string help;
    // Passes whose GPU time is the technique's cost besides its own ("<name>" and "<name>.*"): prefixes
    // of shared passes such as tile classification ("tiles.") or the depth hierarchy ("hiz.").
    std::vector<std::string> sharedCost;
    bool reference = false;  // the ground truth compare, bench and A/B score against
    // Builds the module once per renderer; null for a technique that draws no reflection (none).
    std::unique_ptr<Technique> (*make)(FrameServices&) = nullptr;
};

const std::vector<TechniqueDesc>& techniqueTable();
const TechniqueDesc* findTechnique(const std::string& name);
// Throws std::runtime_error "unknown technique 'x' (available: ...)".
const TechniqueDesc& techniqueDesc(const std::string& name);
std::vector<std::string> techniqueNames();  // in table order (the UI's order)
bool isTechnique(const std::string& name);
bool isSsrTechnique(const std::string& name);  // ssr-brute, ssr-lowq, ssr-hiz, ssr-linear
// Is `pass` part of the technique's cost: its own passes and its sharedCost prefixes.
bool isTechniquePass(const std::string& technique, const std::string& pass);
// Sum of the GPU times of the technique's passes.
double techniqueCost(const std::string& technique, const std::map<std::string, double>& passMs);
// `--technique` lines of `ppr --help`.
std::string techniquesUsage();

}  // namespace ppr::app
