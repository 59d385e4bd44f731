#include "noise.hpp"

#include <cmath>

namespace gen {

uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = seed * 0x9E3779B1u;
    h ^= x * 0x85EBCA77u;
    h = (h << 13) | (h >> 19);
    h ^= y * 0xC2B2AE3Du;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return h;
}

float hash01(uint32_t x, uint32_t y, uint32_t seed) {
    return static_cast<float>(hash3(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

float valueNoise(float u, float v, int period, uint32_t seed) {
    const float x = u * static_cast<float>(period), y = v * static_cast<float>(period);
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    auto at = [&](int cx, int cy) {
        const uint32_t wx = static_cast<uint32_t>(((cx % period) + period) % period);
        const uint32_t wy = static_cast<uint32_t>(((cy % period) + period) % period);
        return hash01(wx, wy, seed);
    };
    const float a = at(ix, iy), b = at(ix + 1, iy), c = at(ix, iy + 1), d = at(ix + 1, iy + 1);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float fbm(float u, float v, int basePeriod, int octaves, uint32_t seed) {
    float sum = 0.0f, amp = 1.0f, norm = 0.0f;
    int period = basePeriod;
    for (int o = 0; o < octaves; ++o) {
        sum += amp * valueNoise(u, v, period, seed + static_cast<uint32_t>(o) * 1013u);
        norm += amp;
        amp *= 0.5f;
        period *= 2;
    }
    return sum / norm;
}

}  // namespace gen
