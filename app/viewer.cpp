#include "viewer.hpp"

#include <cstdlib>
#include <stdexcept>

namespace ppr::app {
bool displayAvailable() { return std::getenv("DISPLAY") || std::getenv("WAYLAND_DISPLAY"); }
int runViewer(const Options&) { throw std::runtime_error("view: the viewer is being written"); }
}  // namespace ppr::app
