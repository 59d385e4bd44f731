// Display mapping (exposure → ACES filmic fit → sRGB encode), shared by the tonemap shader and by
// `ppr compare`, which scores reflections in the same display space the user sees.
#ifndef PPR_TONEMAP_H
#define PPR_TONEMAP_H
#include "shader/shared.h"

PPR_BEGIN
// Narkowicz's ACES filmic fit: cheap, neutral enough for comparing techniques.
PPR_INLINE vec3 acesFilmic(vec3 x) {
    return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}
PPR_INLINE vec3 linearToSrgb(vec3 c) {
    return mix(c * 12.92f, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, step(vec3(0.0031308f), c));
}
// HDR radiance → display value in [0, 1] (what the 8-bit output stores, before quantisation).
PPR_INLINE vec3 displayFromRadiance(vec3 hdr, float exposure) { return linearToSrgb(acesFilmic(hdr * exposure)); }
PPR_END

#endif
