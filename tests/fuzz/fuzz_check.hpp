#pragma once
// What every fuzz target asserts besides "no crash, no sanitizer report": bad input is reported as
// one std::runtime_error line (the interface contract), and a broken invariant aborts with a note,
// which libFuzzer records as a crash together with its input.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ppr::fuzz {

[[noreturn]] inline void broken(const std::string& what) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

inline void check(bool ok, const std::string& what) {
    if (!ok) broken(what);
}

// Any other exception type escaping a parser (nlohmann's type_error, std::out_of_range...) is a bug:
// callers catch only std::runtime_error, so those reach std::terminate and libFuzzer reports them.
inline void checkOneLine(const std::runtime_error& e) {
    const std::string msg = e.what();
    check(!msg.empty(), "empty error message");
    check(msg.find('\n') == std::string::npos && msg.find('\r') == std::string::npos, "error message is not one line: " + msg);
}

}  // namespace ppr::fuzz
