#pragma once
#include "cli/cli.hpp"

namespace ppr::app {
// True when a window can be opened (X11/Wayland display reachable).
bool displayAvailable();
// `ppr view`: GLFW window, fly camera, ImGui overlay. Returns the process exit code.
int runViewer(const Options& options);
}  // namespace ppr::app
