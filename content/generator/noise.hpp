#pragma once
// Deterministic integer hashing and tileable value noise. The generator must write the same bytes
// on every run, so nothing here touches clocks, std::random_device or unspecified-distribution
// std:: random engines.
#include <cstdint>

namespace gen {

// Avalanching 3-input hash (a lowbias32-style finaliser over a mixed key).
uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed);
// hash3 mapped to [0, 1).
float hash01(uint32_t x, uint32_t y, uint32_t seed);

// Bilinear-smoothstep value noise on a lattice with `period` cells per unit, wrapping so that
// u, v in [0, 1) tiles seamlessly. Returns [0, 1].
float valueNoise(float u, float v, int period, uint32_t seed);
// Sum of `octaves` value-noise layers, period doubling and amplitude halving; normalised to [0, 1].
float fbm(float u, float v, int basePeriod, int octaves, uint32_t seed);

}  // namespace gen
