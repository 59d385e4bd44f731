#version 460
#extension GL_GOOGLE_include_directive : require
// TAA resolve of the surface part alone, the history counting its frames (the defaults: taa_split=1,
// taa_average=1).
#define PPR_TAA_SPLIT 1
#define PPR_TAA_AVERAGE 1
#include "taa/taa_body.glsl"
