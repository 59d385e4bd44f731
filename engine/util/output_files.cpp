#include "util/output_files.hpp"

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace ppr::util {

void prepareOutputDirectory(const std::filesystem::path& dir, const std::string& what) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(what + ": cannot create directory " + dir.string() + ": " + ec.message());
    const std::filesystem::path probe = dir / ".ppr-write-check";
    {
        std::ofstream f(probe);
        if (!(f << "ok\n") || !f.flush()) {
            std::filesystem::remove(probe, ec);
            throw std::runtime_error(what + ": directory " + dir.string() + " is not writable");
        }
    }
    std::filesystem::remove(probe, ec);
}

void writeTextFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error(path.string() + ": cannot open for writing");
    f << text;
    f.flush();
    if (!f) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace ppr::util
