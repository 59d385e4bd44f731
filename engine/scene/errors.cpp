#include "scene/errors.hpp"

#include <cstdio>

namespace ppr::scene::detail {

std::string oneLine(std::string text) {
    constexpr size_t kMaxLength = 600;  // a runaway JSON token must not flood the terminal
    for (char& c : text) {
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
        else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';  // raw bytes from a broken file
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    if (text.size() > kMaxLength) text = text.substr(0, kMaxLength) + "...";
    return text;
}

std::string fmtNum(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void fail(const std::string& message) { throw std::runtime_error(oneLine(message)); }

}  // namespace ppr::scene::detail
