#pragma once
// The debug views, listed once: `--set debug=NAME`, the viewer's selector and F2, `--help` and the
// value the shaders switch on (common/frame.h kDebug*) all come from this table.
#include <cstdint>
#include <string>
#include <vector>

namespace ppr::app {

struct DebugViewDecl {
    std::string name;   // --set debug=name
    uint32_t value;     // gpu::kDebug* (FrameConstants::debugView, PPR's reflection pass)
    std::string owner;  // the pass that draws it
    std::string help;
};

const std::vector<DebugViewDecl>& debugViews();
// Throws std::logic_error for a value not in the table.
const DebugViewDecl& debugView(uint32_t value);

}  // namespace ppr::app
