// The planar reference's rule for "the main view shows this reflected point" (so a screen-space
// technique could have it), shared by the planar resolves and the ray-traced reference: it faces the
// main camera, projects on screen, and is the surface the main view's depth shows there (within
// kPlanarVisibleTolerance + kPlanarVisibleTolerancePerMetre × its distance). Needs common/bindings.glsl
// and planar/planar.h.
bool visibleInMainView(sampler2D mainViewDepth, vec3 p, vec3 n) {
    if (dot(n, frame.cameraPos.xyz - p) <= 0.0) return false;
    vec4 clip = frame.viewProj * vec4(p, 1.0);
    if (clip.w <= 0.0) return false;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) return false;
    ivec2 q = ivec2(uv * frame.screenSize);
    float depth = texelFetch(mainViewDepth, q, 0).r;
    if (depth <= 0.0) return false;
    vec3 seen = worldOfPixel(q, depth);
    float tolerance = kPlanarVisibleTolerance + kPlanarVisibleTolerancePerMetre * distance(frame.cameraPos.xyz, p);
    return distance(seen, p) <= tolerance;
}
