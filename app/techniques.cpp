#include "techniques.hpp"

#include <algorithm>

namespace ppr::app {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> list = {"ppr", "planar", "none"};
    return list;
}

bool isTechnique(const std::string& name) {
    const auto& list = techniqueNames();
    return std::find(list.begin(), list.end(), name) != list.end();
}

bool isTechniquePass(const std::string& technique, const std::string& pass) {
    if (technique == "none") return false;
    const std::string prefix = technique + ".";
    return pass.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace ppr::app
