#pragma once
// The reflection techniques this build renders, in the order the UI lists them; `none` draws the lit
// scene without reflections. Used by the CLI, the renderer, reports and the viewer.
#include <string>
#include <vector>

namespace ppr::app {

const std::vector<std::string>& techniqueNames();
bool isTechnique(const std::string& name);
// Passes whose GPU time is the technique's own cost (ppr.* for ppr, planar.* for planar).
bool isTechniquePass(const std::string& technique, const std::string& passName);

}  // namespace ppr::app
