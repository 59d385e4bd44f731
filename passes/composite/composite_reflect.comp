#version 460
#extension GL_GOOGLE_include_directive : require
// Composite with a technique's reflection image blended onto reflector pixels.
#define PPR_COMPOSITE_REFLECTION 1
#include "composite/composite_body.glsl"
