#pragma once
// The reflection techniques this build renders, in the order the UI lists them; `none` draws the lit
// scene without reflections, `floor` is the cost floor of screen-space reflections (draws none). Used by the CLI, the renderer, reports and the viewer.
#include <string>
#include <vector>

namespace ppr::app {

const std::vector<std::string>& techniqueNames();
bool isTechnique(const std::string& name);
// ssr-brute, ssr-lowq, ssr-hiz, ssr-linear.
bool isSsrTechnique(const std::string& name);
// Passes whose GPU time is the technique's own cost: its own ("ssr-brute", "ppr.*", "planar.*"),
// tile classification ("tiles.*") for ppr and the SSR family, the depth hierarchy ("hiz.*") for
// ssr-hiz and ppr (its fallback).
bool isTechniquePass(const std::string& technique, const std::string& passName);

}  // namespace ppr::app
