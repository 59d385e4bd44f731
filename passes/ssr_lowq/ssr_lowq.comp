#version 460
#extension GL_GOOGLE_include_directive : require
#include "ssr_common/ssr_pixel.glsl"

// PLACEHOLDER (being written): misses everywhere.
bool ssrTrace(SsrRay ray, out vec2 hitPixel) {
    hitPixel = vec2(0.0);
    return false;
}
