#pragma once
// Groupings of reflectors the techniques need, computed once per reflector change (pure logic):
// - orientation groups: reflectors of one kind whose normals point the same way (floor puddles and
//   stair treads share one). PPR writes each pixel at most once per orientation — for the shape
//   nearest to it. Glass panels never share one, with anything: a pixel is reflected in every pane
//   that shows it (they are transparent) and in the mirror behind them.
// - plane groups: coplanar reflectors, which one mirrored render serves (the planar ground truth).
#include "scene/reflector.hpp"

#include <cstdint>
#include <vector>

namespace ppr::scene {

struct ReflectorGroups {
    std::vector<uint32_t> orientationGroup;  // per reflector
    std::vector<uint32_t> planeGroup;        // per reflector
    std::vector<uint32_t> projectionOrder;   // reflector indices sorted by orientation group (stable)
    uint32_t orientationGroupCount = 0;
    uint32_t planeGroupCount = 0;
};

constexpr float kParallelCosine = 0.99999f;  // ≈ 0.26° between normals
constexpr float kCoplanarDistance = 1e-3f;   // metres between parallel planes

ReflectorGroups groupReflectors(const std::vector<Reflector>& reflectors);

}  // namespace ppr::scene
