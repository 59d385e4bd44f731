#version 460
#extension GL_GOOGLE_include_directive : require
// Clears a float (or normalised) image: the clear value's bits read as floats.
#define CLEAR_IMAGE image2D
#define CLEAR_VALUE(bits) uintBitsToFloat(bits)
#include "common/clear.glsl"
