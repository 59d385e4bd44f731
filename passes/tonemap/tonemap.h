// Display mapping (exposure → ACES filmic fit → sRGB encode), shared by the tonemap shader and by
// `ppr compare`, which scores reflections in the same display space the user sees.
#ifndef PPR_TONEMAP_H
#define PPR_TONEMAP_H
#include "shader/shared.h"

PPR_BEGIN
// The pass's push constants. A target larger than the frame (the viewer's --render-scale) is filled
// by bilinear upscaling of the HDR image; one of the frame's size reads its texels as they are.
struct TonemapPush {
    vec2 invTargetSize;  // 1 / target extent (upscale only)
    uint upscale;        // 1: the target is larger than the HDR image
    uint pad;
};
// Narkowicz's ACES filmic fit: cheap, neutral enough for comparing techniques.
PPR_INLINE vec3 acesFilmic(vec3 x) {
    return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}
PPR_INLINE vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92f, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, step(vec3(0.0031308f), c));
}
// HDR radiance → display value in [0, 1] (what the 8-bit output stores, before quantisation).
PPR_INLINE vec3 displayFromRadiance(vec3 hdr, float exposure) { return linearToSrgb(acesFilmic(hdr * exposure)); }
// The inverse, for overlays that must show an exact display colour (the A/B error heat map): display
// values above 0.99 map to 0.99 (the fit reaches 1 only at infinity).
PPR_INLINE vec3 srgbToLinear(vec3 c) { return mix(c / 12.92f, pow((c + 0.055f) / 1.055f, vec3(2.4f)), step(vec3(0.04045f), c)); }
PPR_INLINE vec3 radianceFromDisplay(vec3 display, float exposure) {
    vec3 y = clamp(srgbToLinear(clamp(display, 0.0f, 1.0f)), 0.0f, 0.99f);
    vec3 a = 2.51f - 2.43f * y, b = 0.03f - 0.59f * y, c = -0.14f * y;
    return (-b + sqrt(b * b - 4.0f * a * c)) / (2.0f * a) / exposure;
}
PPR_END
PPR_SIZE_CHECK(TonemapPush, 16);

#endif
