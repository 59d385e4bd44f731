#pragma once
// The scale scene (docs/scenes.md): what a large exported level asks of the loader and renderer —
// over a million triangles, over a thousand materials and over five hundred textures — around one
// reflective floor, so PPR's cost can be compared with the default scene's.
#include <string>

namespace gen {

// Writes scale.gltf, scale.bin, the PNG textures (textures/) and scale.reflectors.json into `dir`
// (which must exist). Each sphere has `segments` × segments/2 quads (32: 960 triangles, 1 045 440
// in the scene); the layout does not change with it, so only the triangle count does.
// Deterministic: the same bytes on every run.
constexpr int kScaleDefaultSegments = 32;
void writeScaleScene(const std::string& dir, int segments = kScaleDefaultSegments);

}  // namespace gen
