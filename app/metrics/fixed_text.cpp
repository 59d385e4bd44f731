#include "metrics/fixed_text.hpp"

#include <cstdio>

namespace ppr::app {

std::string fixedText(double value, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, value);
    return buf;
}

}  // namespace ppr::app
