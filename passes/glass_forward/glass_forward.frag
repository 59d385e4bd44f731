#version 460
#extension GL_GOOGLE_include_directive : require
// Glass without reflections (--set glass=0, or a technique with no glass reflection).
#include "glass_forward/glass_forward_body.glsl"
