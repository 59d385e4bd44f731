#pragma once
// Procedural, tileable material textures. Each surface is built from a height field (which also
// yields the normal map via finite differences), a base colour (sRGB bytes) and a glTF
// metallic-roughness image (G = roughness, B = metallic, R unused = 255).
#include <cstdint>
#include <string>
#include <vector>

namespace gen {

struct Image {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // 3 channels, row-major, top row first
};

struct TextureSet {
    Image baseColor, normal, metallicRoughness;
};

// Tangent-space normal map (OpenGL convention: +Y / green points to the top of the image) from a
// wrapping height field given in texels; `strength` scales the slopes.
Image normalMapFromHeight(const std::vector<float>& height, int width, int heightPx, float strength);

TextureSet floorTiles(int size);  // 4x4 stone slabs with grout
TextureSet bricks(int size);      // 8 rows of staggered bricks with mortar
TextureSet sandstone(int size);   // 4 rows of large ashlar blocks
Image marble(int size);           // polished dark marble with light veins (base colour only)

// Normal-mapped reflectors (the slides' normal-map approximation is measured on them):
Image rippleNormals(int size);     // rain ripples on water: rings around a few drop centres (normal map only)
TextureSet polishedTiles(int size);  // 4x4 glossy tiles with bevelled edges and grout lines
Image wavyGlassNormals(int size);  // old drawn mirror glass: long gentle waves (normal map only)

// Writes an RGB PNG with a fixed compression level, so the bytes are reproducible.
void writePng(const std::string& path, const Image& image);

}  // namespace gen
