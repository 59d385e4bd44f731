#include "techniques.hpp"

#include <algorithm>

namespace ppr::app {

const std::vector<std::string>& techniqueNames() {
    static const std::vector<std::string> list = {"ppr", "ssr-brute", "ssr-lowq", "ssr-hiz", "ssr-linear", "planar", "floor", "none"};
    return list;
}

bool isTechnique(const std::string& name) {
    const auto& list = techniqueNames();
    return std::find(list.begin(), list.end(), name) != list.end();
}

bool isSsrTechnique(const std::string& name) { return name.rfind("ssr-", 0) == 0 && isTechnique(name); }

bool isTechniquePass(const std::string& technique, const std::string& pass) {
    if (technique == "none") return false;
    auto startsWith = [&](const std::string& prefix) { return pass.compare(0, prefix.size(), prefix) == 0; };
    if (pass == technique || startsWith(technique + ".")) return true;
    // Tile classification serves PPR and the SSR techniques; the depth hierarchy serves ssr-hiz and
    // PPR's fallback on non-planar tiles.
    const bool classifies = technique == "ppr" || isSsrTechnique(technique);
    if (classifies && startsWith("tiles.")) return true;
    return (technique == "ssr-hiz" || technique == "ppr") && startsWith("hiz.");
}

}  // namespace ppr::app
