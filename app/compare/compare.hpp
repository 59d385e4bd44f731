#pragma once
#include "cli/cli.hpp"

namespace ppr::app {
// `ppr compare`: for each camera renders the planar ground truth and every --technique, scores each
// technique's reflection against it (compare_metrics.hpp, docs/quality.md) and writes contact.png,
// metrics.json and the per-technique images. Returns the exit code (1 on validation errors).
int runCompare(const Options& options);
}  // namespace ppr::app
