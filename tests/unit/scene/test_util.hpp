#pragma once
// Shared helpers for the scene unit tests: temporary directories, file I/O, error-message checks.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

namespace ppr::scene::test {

inline std::string dataPath(const std::string& rel) { return std::string(PPR_TEST_DATA_DIR) + "/" + rel; }

// A fresh directory removed at scope exit.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        static int counter = 0;
        path = std::filesystem::temp_directory_path() /
               ("ppr_scene_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// Runs f, expecting std::runtime_error whose message is one line containing every `parts` entry.
// Returns the message so callers can print or check more.
inline std::string expectError(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.find('\n'), std::string::npos) << "not one line: " << msg;
        for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing in: " << msg;
        return msg;
    }
    ADD_FAILURE() << "no std::runtime_error thrown (expected one containing '" << (parts.empty() ? "" : parts[0]) << "')";
    return "";
}

}  // namespace ppr::scene::test
