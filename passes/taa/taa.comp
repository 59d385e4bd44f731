#version 460
#extension GL_GOOGLE_include_directive : require
// TAA resolve of the whole colour (taa_split=0, or a technique without a reflection image).
#include "taa/taa_body.glsl"
