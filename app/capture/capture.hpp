#pragma once
#include "cli/cli.hpp"

namespace ppr::app {
// `ppr capture`: renders each requested camera headlessly, writes final.png + report.json.
// Returns the process exit code (1 when validation reported errors).
int runCapture(const Options& options);
}  // namespace ppr::app
