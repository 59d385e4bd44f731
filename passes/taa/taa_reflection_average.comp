#version 460
#extension GL_GOOGLE_include_directive : require
// The reflection's own history counting its frames (taa_average=1, the default).
#define PPR_TAA_AVERAGE 1
#include "taa/taa_reflection_body.glsl"
