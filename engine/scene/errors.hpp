#pragma once
// Internal to ppr_scene: the one-line error convention of the interface contract
// ("<file>: <field>: <problem>") in one place, so every loader formats failures the same way.
#include <stdexcept>
#include <string>

namespace ppr::scene::detail {

// Newlines/tabs become spaces and the text is capped, so a message always prints as one line.
std::string oneLine(std::string text);
// Short human number for messages (%g: "1.2", "0.0001").
std::string fmtNum(double v);
[[noreturn]] void fail(const std::string& message);  // throws std::runtime_error(oneLine(message))

}  // namespace ppr::scene::detail
