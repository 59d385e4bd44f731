#pragma once
// `ppr fit`: reflector rectangles fitted to a whole scene's flat surfaces (scene/planar_regions.hpp),
// printed as a table and written as a reflector file that view, capture and compare load as it is.
#include "cli/cli.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace ppr::app {

// Which materials `ppr fit` considers: those matching every criterion given (--materials, an
// ECMAScript regular expression searched in the name; --max-roughness, the roughness factor); with
// neither, the materials marked reflective (extras "ppr_reflective"). Throws naming the option when
// the expression is invalid or nothing is selected.
std::vector<bool> selectFitMaterials(const scene::Scene& scene, const Options& options);
// The file `ppr fit` writes: --out when given, else out/<scene stem>.reflectors.json.
std::string fitOutputPath(const Options& options);

int runFit(const Options& options);

}  // namespace ppr::app
