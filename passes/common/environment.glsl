// The environment behind screen-space reflections (--set fallback_env): what a reflected ray that
// leaves the screen or finds nothing shows, and how a hit near the screen border fades into it, so
// the edge of the screen is not a visible seam. The environment is the sky the lighting pass draws
// (common/brdf.glsl skyRadiance); the scene has no reflection probe (see docs/normalmaps.md).
// Needs common/bindings.glsl, common/brdf.glsl and common/reflection.h.

vec3 environmentRadiance(vec3 reflectedDir) { return skyRadiance(normalize(reflectedDir)); }

// 1 well inside the screen, falling to 0 at its border (pixel coordinates of the sample).
float environmentEdgeWeight(vec2 pixel) {
    vec2 d = min(pixel, frame.screenSize - pixel);
    float band = kEnvironmentEdgeFade * min(frame.screenSize.x, frame.screenSize.y);
    return smoothstep(0.0, band, min(d.x, d.y));
}

// A screen-space hit at `pixel` seen along `reflectedDir`, faded into the environment at the border.
vec3 environmentBlend(vec3 hitColor, vec2 pixel, vec3 reflectedDir) {
    return mix(environmentRadiance(reflectedDir), hitColor, environmentEdgeWeight(pixel));
}
