#version 460
#extension GL_GOOGLE_include_directive : require
// TAA resolve of the surface part alone; the reflection's own resolved history is added after
// (taa_split=1 with a technique's reflection image).
#define PPR_TAA_SPLIT 1
#include "taa/taa_body.glsl"
