#pragma once
// Output files of capture, compare and bench: a directory proven writable before anything renders (so
// a long run is not lost at its end), and text written with every failure reported (a full disk).
#include <filesystem>
#include <string>

namespace ppr::util {

// Creates `dir` (and parents) and checks a file can be written in it. Throws std::runtime_error with
// one line naming `what` (e.g. "--out out") and the reason.
void prepareOutputDirectory(const std::filesystem::path& dir, const std::string& what);

// Writes `text` to `path`; throws "<path>: cannot open for writing" or "<path>: write failed".
void writeTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace ppr::util
