#version 460
#extension GL_GOOGLE_include_directive : require
// Clears an unsigned integer image.
#define CLEAR_IMAGE uimage2D
#define CLEAR_VALUE(bits) (bits)
#include "common/clear.glsl"
