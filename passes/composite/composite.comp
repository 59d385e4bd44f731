#version 460
#extension GL_GOOGLE_include_directive : require
// Composite without a reflection technique (--technique none).
#include "composite/composite_body.glsl"
