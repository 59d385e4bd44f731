#version 460
#extension GL_GOOGLE_include_directive : require
// Glass with its reflection from the atlas.
#define GLASS_REFLECTION 1
#include "glass_forward/glass_forward_body.glsl"
