#pragma once
// Built-in procedural scene for scaling measurements: `--scene stress:N` lays N mirror tiles over a
// fixed 16 x 16 m floor, so that the cost difference between N = 1 and N = 1024 is the reflector
// count and not the geometry (the tiled area stays the same for every N). Built in memory.
#include "scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace ppr::scene {

constexpr uint32_t kStressMaxTiles = 4096;
constexpr float kStressFloorSize = 16.0f;     // metres, the square the tiles cover, centred at the origin
constexpr float kStressTileFill = 0.92f;      // tile size / cell size along each axis (rest is grout)
constexpr float kStressTileHeight = 0.002f;   // tiles float above the grout floor at y = 0

// "stress:N" → N; std::nullopt when `spec` does not start with "stress:". Throws std::runtime_error
// ("--scene <spec>: expected stress:N with N a whole number in 1..4096") for a bad N.
std::optional<uint32_t> parseStressSpec(const std::string& spec);

// N mirror tiles (draw i bound to reflector i, named "tile_<i>"), a grout floor, coloured props,
// two walls and the cameras overview, reflective_5, reflective_25, reflective_100.
// Throws std::runtime_error when tileCount is outside 1..kStressMaxTiles.
Scene makeStressScene(uint32_t tileCount);

}  // namespace ppr::scene
