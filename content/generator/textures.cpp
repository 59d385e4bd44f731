#include "textures.hpp"

#include "noise.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gen {

namespace {

struct Rgb {
    float r, g, b;
};

Rgb blend(const Rgb& a, const Rgb& b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}
Rgb scale(const Rgb& a, float s) { return {a.r * s, a.g * s, a.b * s}; }

uint8_t toByte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

void put(Image& img, int x, int y, const Rgb& c) {
    uint8_t* p = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
    p[0] = toByte(c.r);
    p[1] = toByte(c.g);
    p[2] = toByte(c.b);
}

Image blank(int size) {
    Image img;
    img.width = img.height = size;
    img.rgb.assign(static_cast<size_t>(size) * size * 3, 0);
    return img;
}

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Metallic-roughness texel for a dielectric: R unused, G roughness, B metallic = 0.
Rgb roughnessTexel(float roughness) { return {1.0f, roughness, 0.0f}; }

// Running-bond masonry cell lookup: which block (cx, cy) a texel falls in and its distance to the
// nearest joint, with every odd row shifted by half a block.
struct Cell {
    int cx, cy;
    float edge;  // texels to the nearest joint centre line
    uint32_t id() const { return static_cast<uint32_t>(cy * 16 + cx); }  // seeds the block's own noise
};
Cell masonryCell(int x, int y, int blockW, int blockH, int size, bool stagger) {
    const int cy = y / blockH;
    const int shift = (stagger && (cy & 1)) ? blockW / 2 : 0;
    const int xs = (x + shift) % size;
    const int cx = xs / blockW;
    const float lx = static_cast<float>(xs % blockW) + 0.5f, ly = static_cast<float>(y % blockH) + 0.5f;
    const float edge = std::min(std::min(lx, static_cast<float>(blockW) - lx), std::min(ly, static_cast<float>(blockH) - ly));
    // Wrap the column index so the shifted last block matches the first (tileable).
    return {cx % (size / blockW), cy, edge};
}

// What a material generator says about one texel.
struct Texel {
    Rgb color;
    float height;     // for the normal map
    float roughness;  // for the metallic-roughness image
};

// The wrapping height field of `size`² texels given per texel centre (u, v in [0, 1)).
template <class HeightAt>
std::vector<float> heightField(int size, HeightAt heightAt) {
    std::vector<float> height(static_cast<size_t>(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) height[static_cast<size_t>(y) * size + x] = heightAt(x, y, (x + 0.5f) / size, (y + 0.5f) / size);
    return height;
}

// A material's three images from its texels (texelAt(x, y, u, v) → Texel), the normal map from the
// heights with `bumpStrength`.
template <class TexelAt>
TextureSet textureSet(int size, float bumpStrength, TexelAt texelAt) {
    TextureSet set{blank(size), {}, blank(size)};
    const std::vector<float> height = heightField(size, [&](int x, int y, float u, float v) {
        const Texel t = texelAt(x, y, u, v);
        put(set.baseColor, x, y, t.color);
        put(set.metallicRoughness, x, y, roughnessTexel(t.roughness));
        return t.height;
    });
    set.normal = normalMapFromHeight(height, size, size, bumpStrength);
    return set;
}

}  // namespace

Image normalMapFromHeight(const std::vector<float>& h, int w, int hgt, float strength) {
    Image img = blank(w);
    img.height = hgt;
    img.rgb.assign(static_cast<size_t>(w) * hgt * 3, 0);
    auto at = [&](int x, int y) { return h[static_cast<size_t>((y + hgt) % hgt) * w + (x + w) % w]; };
    for (int y = 0; y < hgt; ++y) {
        for (int x = 0; x < w; ++x) {
            const float dx = 0.5f * (at(x + 1, y) - at(x - 1, y));
            const float dyDown = 0.5f * (at(x, y + 1) - at(x, y - 1));
            // Image "up" is −row, so the up-slope is −dyDown; the normal leans against the slope.
            float nx = -dx * strength, ny = dyDown * strength, nz = 1.0f;
            const float len = std::sqrt(nx * nx + ny * ny + nz * nz);
            nx /= len;
            ny /= len;
            nz /= len;
            put(img, x, y, {nx * 0.5f + 0.5f, ny * 0.5f + 0.5f, nz * 0.5f + 0.5f});
        }
    }
    return img;
}

TextureSet floorTiles(int size) {
    const int tile = size / 4;
    const Rgb stoneA{0.60f, 0.58f, 0.54f}, stoneB{0.72f, 0.68f, 0.61f}, stoneC{0.52f, 0.53f, 0.55f};
    const Rgb grout{0.30f, 0.29f, 0.27f};
    return textureSet(size, 2.0f, [&](int x, int y, float u, float v) {
        const Cell c = masonryCell(x, y, tile, tile, size, false);
        const uint32_t id = c.id();
        const float slab = smoothstep(2.0f, 5.5f, c.edge);
        const float coarse = fbm(u, v, 4, 3, 11u + id);  // per-slab cloudiness
        const float fine = fbm(u, v, 16, 4, 23u);
        const float pick = hash01(id, 0, 7u);
        Rgb stone = pick < 0.45f ? blend(stoneA, stoneB, hash01(id, 1, 7u)) : pick < 0.8f ? stoneB : stoneC;
        stone = scale(stone, 0.82f + 0.22f * coarse + 0.12f * (fine - 0.5f));
        // Dark pits where the fine noise dips, for texture at close range.
        const float pit = smoothstep(0.30f, 0.24f, fine);
        stone = scale(stone, 1.0f - 0.12f * pit);
        return Texel{.color = blend(grout, stone, slab),
                     .height = slab * (0.85f + 0.1f * hash01(id, 2, 7u)) + 0.25f * (fine - 0.5f) * slab - 0.3f * pit,
                     .roughness = 0.95f - slab * (0.22f - 0.12f * coarse)};
    });
}

TextureSet bricks(int size) {
    const int bw = size / 4, bh = size / 8;
    const Rgb palette[4] = {{0.58f, 0.26f, 0.18f}, {0.66f, 0.33f, 0.22f}, {0.50f, 0.22f, 0.16f}, {0.70f, 0.42f, 0.30f}};
    const Rgb mortar{0.66f, 0.63f, 0.58f};
    return textureSet(size, 2.5f, [&](int x, int y, float u, float v) {
        const Cell c = masonryCell(x, y, bw, bh, size, true);
        const uint32_t id = c.id();
        const float brick = smoothstep(3.0f, 6.0f, c.edge);
        const float fine = fbm(u, v, 16, 4, 41u);
        const float blotch = fbm(u, v, 8, 3, 43u + id);
        Rgb col = palette[hash3(id, 3, 5u) % 4];
        col = scale(col, 0.85f + 0.25f * blotch + 0.15f * (fine - 0.5f));
        // A few soot-darkened bricks break up the repetition.
        if (hash01(id, 4, 5u) < 0.12f) col = scale(col, 0.7f);
        return Texel{.color = blend(scale(mortar, 0.9f + 0.2f * fine), col, brick),
                     .height = 0.15f + brick * (0.85f + 0.3f * (blotch - 0.5f)) + 0.2f * (fine - 0.5f),
                     .roughness = brick > 0.5f ? 0.8f + 0.1f * fine : 0.95f};
    });
}

TextureSet sandstone(int size) {
    const int bw = size / 2, bh = size / 4;
    const Rgb base{0.80f, 0.70f, 0.54f}, joint{0.55f, 0.49f, 0.40f};
    return textureSet(size, 1.5f, [&](int x, int y, float u, float v) {
        const Cell c = masonryCell(x, y, bw, bh, size, true);
        const uint32_t id = c.id();
        const float block = smoothstep(1.0f, 3.5f, c.edge);
        const float fine = fbm(u, v, 16, 3, 61u);
        const float coarse = fbm(u, v, 4, 3, 67u + id);
        // Sedimentary strata: horizontal bands bent by noise (integer frequency keeps it tileable).
        const float strata = 0.5f + 0.5f * std::sin(6.2831853f * (16.0f * v) + 2.0f * coarse);
        Rgb col = scale(base, 0.86f + 0.14f * hash01(id, 1, 9u) + 0.1f * (coarse - 0.5f) - 0.03f * strata);
        return Texel{.color = blend(joint, col, block),
                     .height = block * (0.9f + 0.2f * (coarse - 0.5f)) + 0.15f * (fine - 0.5f),
                     .roughness = 0.85f + 0.1f * fine};
    });
}

Image marble(int size) {
    Image img = blank(size);
    const Rgb dark{0.13f, 0.13f, 0.14f}, vein{0.78f, 0.77f, 0.74f};
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float u = (x + 0.5f) / size, v = (y + 0.5f) / size;
            const float turb = fbm(u, v, 4, 4, 81u);
            // Integer frequencies in u and v keep the veins continuous across the tile border.
            const float s = std::sin(6.2831853f * (2.0f * u + 1.0f * v) + 7.0f * turb);
            const float veinMask = std::pow(1.0f - std::fabs(s), 10.0f);
            const float cloud = fbm(u, v, 8, 3, 83u);
            put(img, x, y, blend(scale(dark, 0.85f + 0.3f * cloud), vein, 0.8f * veinMask));
        }
    }
    return img;
}

Image rippleNormals(int size) {
    // Wrapped (torus) distance to each drop keeps the map tileable; each ring train is a damped
    // sine of the distance, so the slopes are gentle except close to the drop.
    struct Drop {
        float x, y, phase, amplitude;
    };
    const Drop drops[] = {{0.21f, 0.30f, 0.0f, 1.0f}, {0.68f, 0.18f, 1.7f, 0.8f}, {0.47f, 0.71f, 3.1f, 1.0f},
                          {0.85f, 0.80f, 0.6f, 0.7f}, {0.10f, 0.84f, 2.2f, 0.6f}};
    const std::vector<float> height = heightField(size, [&](int, int, float u, float v) {
        float h = 0.0f;
        for (const Drop& d : drops) {
            float dx = std::fabs(u - d.x), dy = std::fabs(v - d.y);
            dx = std::min(dx, 1.0f - dx);
            dy = std::min(dy, 1.0f - dy);
            const float r = std::sqrt(dx * dx + dy * dy);
            h += d.amplitude * std::sin(6.2831853f * 9.0f * r - d.phase) * std::exp(-7.0f * r);
        }
        return h;
    });
    return normalMapFromHeight(height, size, size, 1.2f);
}

TextureSet polishedTiles(int size) {
    const int tile = size / 4;
    const Rgb tileA{0.74f, 0.72f, 0.68f}, tileB{0.66f, 0.64f, 0.61f};
    const Rgb grout{0.22f, 0.21f, 0.20f};
    return textureSet(size, 3.0f, [&](int x, int y, float u, float v) {
        const Cell c = masonryCell(x, y, tile, tile, size, false);
        const uint32_t id = c.id();
        // Grout 2 texels wide, then a rounded bevel over the next 6 texels, then a flat glossy top.
        const float bevel = smoothstep(1.5f, 8.0f, c.edge);
        const float inGrout = 1.0f - smoothstep(1.0f, 2.0f, c.edge);
        const float cloud = fbm(u, v, 4, 3, 131u + id);
        const Rgb stone = scale(((c.cx + c.cy) & 1) ? tileA : tileB, 0.92f + 0.12f * cloud);
        return Texel{.color = blend(stone, grout, inGrout),
                     .height = std::sqrt(bevel) * 0.9f - 0.25f * inGrout,
                     .roughness = 0.04f + 0.7f * inGrout};
    });
}

Image wavyGlassNormals(int size) {
    const std::vector<float> height = heightField(size, [](int, int, float u, float v) {
        // Integer frequencies keep it tileable; the drawing direction is vertical (long waves in v).
        return std::sin(6.2831853f * (3.0f * u + 0.5f * std::sin(6.2831853f * v))) +
               0.35f * std::sin(6.2831853f * (7.0f * u + 2.0f * v)) + 0.6f * (fbm(u, v, 4, 3, 151u) - 0.5f);
    });
    return normalMapFromHeight(height, size, size, 1.0f);
}

void writePng(const std::string& path, const Image& image) {
    // Fixed settings: the library default could change between stb versions.
    stbi_write_png_compression_level = 9;
    stbi_write_force_png_filter = -1;
    if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(), image.width * 3))
        throw std::runtime_error(path + ": cannot write PNG");
}

}  // namespace gen
