#version 460
#extension GL_GOOGLE_include_directive : require
// The reflection's own history with the luma-driven feedback alone (taa_average=0).
#include "taa/taa_reflection_body.glsl"
