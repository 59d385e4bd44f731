#pragma once
// Connectivity for the reflector fits (reflector_fit.cpp's region under a point, planar_regions.cpp's
// whole-scene regions): union-find over triangles, and vertices welded by position through a hash
// grid whose cell is the weld distance.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace ppr::scene {

class UnionFind {
public:
    explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
        return x;
    }
    void unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<uint32_t> parent_;
};

// Calls pair(earlier, later) once for every two vertices (indices 0..count-1, positions from
// position(i)) closer than `weld`, the earlier one first.
template <class Position, class Pair>
void forEachWeldedPair(size_t count, Position position, double weld, Pair pair) {
    struct Key {
        int64_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const { return size_t(k.x * 73856093LL) ^ size_t(k.y * 19349663LL) ^ size_t(k.z * 83492791LL); }
    };
    std::unordered_map<Key, std::vector<uint32_t>, KeyHash> grid;  // cell -> vertex ids
    grid.reserve(count);
    for (uint32_t v = 0; v < count; ++v) {
        const glm::dvec3 p = position(v);
        const Key c{int64_t(std::floor(p.x / weld)), int64_t(std::floor(p.y / weld)), int64_t(std::floor(p.z / weld))};
        for (int64_t dx = -1; dx <= 1; ++dx)
            for (int64_t dy = -1; dy <= 1; ++dy)
                for (int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find(Key{c.x + dx, c.y + dy, c.z + dz});
                    if (it == grid.end()) continue;
                    for (uint32_t w : it->second)
                        if (glm::length(position(w) - p) <= weld) pair(w, v);
                }
        grid[c].push_back(v);
    }
}

}  // namespace ppr::scene
