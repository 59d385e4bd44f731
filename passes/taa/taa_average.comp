#version 460
#extension GL_GOOGLE_include_directive : require
// TAA resolve of the whole colour, the history counting its frames (taa_split=0, taa_average=1).
#define PPR_TAA_AVERAGE 1
#include "taa/taa_body.glsl"
