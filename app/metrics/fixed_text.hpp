#pragma once
// A number as the tables and logs print it: fixed point with a given count of digits.
#include <string>

namespace ppr::app {

std::string fixedText(double value, int digits);

}  // namespace ppr::app
