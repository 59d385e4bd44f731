#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting of a G-buffer without an emissive target (no opaque material emits).
#include "lighting/lighting_body.glsl"
