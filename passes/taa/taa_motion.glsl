// TAA's reprojection, shared by the resolve and the `motion` debug view (needs common/bindings.glsl).
// Where the surface seen at `uv` (a pixel centre of this jittered frame) with reverse-Z `depth` lay on
// last frame's screen: through the world position (homogeneous throughout, so the sky at depth 0 moves
// as a direction) and last frame's unjittered view-projection. Motion is measured between unjittered
// positions, so a still camera gives `uv` itself. `prevW` ≤ 0: the point was behind last frame's camera.
// previousUvOfPoint: the same for any homogeneous world point this frame shows at `uv` (a reflection's
// virtual point lies on the pixel's view ray too).
vec2 previousUvOfPoint(vec2 uv, vec4 world, out float prevW) {
    vec4 prevClip = frame.prevViewProj * world;
    prevW = prevClip.w;
    return uv + 0.5 * (prevClip.xy / prevClip.w - (uv * 2.0 - 1.0 - frame.jitter.xy));
}
// The homogeneous world point this frame shows at `uv` with reverse-Z `depth`.
vec4 worldOfPixel(vec2 uv, float depth) { return frame.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0); }
vec2 previousUv(vec2 uv, float depth, out float prevW) { return previousUvOfPoint(uv, worldOfPixel(uv, depth), prevW); }

