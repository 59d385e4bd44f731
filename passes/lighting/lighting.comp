#version 460
#extension GL_GOOGLE_include_directive : require
// Lighting with the G-buffer's emissive target added.
#define PPR_LIGHTING_EMISSIVE 1
#include "lighting/lighting_body.glsl"
