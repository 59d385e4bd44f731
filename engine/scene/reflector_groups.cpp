#include "scene/reflector_groups.hpp"

#include <algorithm>
#include <numeric>

namespace ppr::scene {

ReflectorGroups groupReflectors(const std::vector<Reflector>& rs) {
    ReflectorGroups g;
    const size_t n = rs.size();
    g.orientationGroup.assign(n, 0);
    g.planeGroup.assign(n, 0);
    // First-come representatives: a reflector joins the first group whose representative matches.
    std::vector<size_t> orientationRep, planeRep;
    for (size_t i = 0; i < n; ++i) {
        const Reflector& r = rs[i];
        // Glass panels each keep their own group: panes overlapping on screen all show their reflection.
        auto o = r.kind == ReflectorKind::Glass ? orientationRep.end()
                                                : std::find_if(orientationRep.begin(), orientationRep.end(), [&](size_t j) {
                                                      return rs[j].kind == r.kind && glm::dot(rs[j].normal, r.normal) >= kParallelCosine;
                                                  });
        if (o == orientationRep.end()) {
            g.orientationGroup[i] = static_cast<uint32_t>(orientationRep.size());
            orientationRep.push_back(i);
        } else {
            g.orientationGroup[i] = static_cast<uint32_t>(o - orientationRep.begin());
        }
        auto p = std::find_if(planeRep.begin(), planeRep.end(), [&](size_t j) {
            return glm::dot(rs[j].normal, r.normal) >= kParallelCosine && std::abs(rs[j].planeDistance(r.center)) <= kCoplanarDistance;
        });
        if (p == planeRep.end()) {
            g.planeGroup[i] = static_cast<uint32_t>(planeRep.size());
            planeRep.push_back(i);
        } else {
            g.planeGroup[i] = static_cast<uint32_t>(p - planeRep.begin());
        }
    }
    g.orientationGroupCount = static_cast<uint32_t>(orientationRep.size());
    g.planeGroupCount = static_cast<uint32_t>(planeRep.size());
    g.projectionOrder.resize(n);
    std::iota(g.projectionOrder.begin(), g.projectionOrder.end(), 0u);
    std::stable_sort(g.projectionOrder.begin(), g.projectionOrder.end(),
                     [&](uint32_t a, uint32_t b) { return g.orientationGroup[a] < g.orientationGroup[b]; });
    return g;
}

}  // namespace ppr::scene
