// Reflector files on disk: loading, and the editor's crash-safe save (temp file + fsync + rename).
#include "scene/reflector.hpp"

#include "scene/errors.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace ppr::scene {

using detail::fail;
namespace fs = std::filesystem;

namespace {

constexpr std::uintmax_t kMaxFileBytes = 64u << 20;  // a reflector file is a few KB; refuse absurd input

void writeAll(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::system_error(errno, std::generic_category(), "write");
        done += static_cast<size_t>(n);
    }
}

void syncDirectoryOf(const fs::path& path) {  // makes the rename itself durable; best effort
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

}  // namespace

std::vector<Reflector> loadReflectorFile(const std::string& path) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (!fs::exists(status)) fail(path + ": no such file");
    if (!fs::is_regular_file(status)) fail(path + ": not a regular file");
    if (fs::file_size(path, ec) > kMaxFileBytes) fail(path + ": file too large for a reflector file");
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in && !in.eof()) fail(path + ": cannot read: " + std::strerror(errno));
    return parseReflectorFile(text.str(), path);
}

void saveReflectorFileAtomic(const std::string& path, const std::vector<Reflector>& reflectors) {
    // Refuse to write what could not be loaded back.
    std::map<std::string, size_t> seen;
    for (size_t i = 0; i < reflectors.size(); ++i) {
        const std::string where = path + ": reflectors[" + std::to_string(i) + "]";
        if (auto problem = validateReflector(reflectors[i]); !problem.empty()) fail(where + "." + problem);
        if (auto [it, inserted] = seen.emplace(reflectors[i].name, i); !inserted)
            fail(where + ".name: duplicate name '" + reflectors[i].name + "' (also reflectors[" + std::to_string(it->second) + "])");
    }
    const std::string text = reflectorsToJson(reflectors);
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path + ": cannot save: " + tmp + ": " + std::strerror(errno));
    try {
        writeAll(fd, text);
        if (::fsync(fd) != 0) throw std::system_error(errno, std::generic_category(), "fsync");
        if (::close(fd) != 0) {
            const int err = errno;
            ::unlink(tmp.c_str());
            fail(path + ": cannot save: close: " + std::strerror(err));
        }
    } catch (const std::system_error& e) {
        ::close(fd);
        ::unlink(tmp.c_str());
        fail(path + ": cannot save: " + e.what());
    }
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        ::unlink(tmp.c_str());
        fail(path + ": cannot save: rename: " + ec.message());
    }
    syncDirectoryOf(path);
}

}  // namespace ppr::scene
