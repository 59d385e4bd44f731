#pragma once
#include "cli/cli.hpp"

#include <string>

namespace ppr::app {
// `ppr compare`: for each camera renders the planar ground truth and every --technique, scores each
// technique's reflection against it (compare_metrics.hpp, docs/quality.md) and writes contact.png,
// metrics.json and the per-technique images. Returns the exit code (1 on validation errors).
int runCompare(const Options& options);
// `ppr compare --path`: every frame of the camera path scored against the reference supersampled 16
// times (compare_path.cpp, docs/temporal.md); metrics.json gives each technique a "temporal" block.
int runComparePath(const Options& options);
// "ppr@normalmap=off,holes=0" → "ppr_normalmap-off_holes-0": a variant's name as a file name.
std::string variantFileName(std::string variant);
}  // namespace ppr::app
