#version 460
#extension GL_GOOGLE_include_directive : require
// The G-buffer with its emissive target (a scene with an opaque material that emits).
#define PPR_GBUFFER_EMISSIVE 1
#include "gbuffer/gbuffer_body.glsl"
