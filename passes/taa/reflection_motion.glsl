// Where last frame showed the reflection seen at `uv` (needs taa_motion.glsl and the includer's
// `motions[]`, gpu::MotionData). The reflection moves with its virtual point: the reflected point
// mirrored through the surface's tangent plane (point `surface`, normal `n`), which lies on the view
// ray (unit `view`) at the reflected path's length `dist`. A reflected point on a moving draw (motion
// `slot` != 0) is first carried to where that draw was, its displacement mirrored through the same
// plane; written as a displacement so that a still one (slot 0, or an identity matrix) adds exactly
// nothing. `prevW` <= 0: behind last frame's camera.
// The reflected point itself, and where a point on the draw of motion `slot` was last frame.
vec3 reflectedPoint(vec3 surface, vec3 view, vec3 n, float dist) {
    return surface + reflect(view, n) * max(dist - length(surface - frame.cameraPos.xyz), 0.0);
}
vec3 pointBefore(vec3 p, uint slot) { return slot == 0u ? p : (motions[slot].toPrevious * vec4(p, 1.0)).xyz; }

vec2 previousUvOfReflection(vec2 uv, vec3 surface, vec3 view, vec3 n, float dist, uint slot, out float prevW) {
    vec4 virtualPoint = vec4(frame.cameraPos.xyz + view * dist, 1.0);
    if (slot != 0u) {
        vec3 reflected = reflectedPoint(surface, view, n, dist);
        vec3 moved = pointBefore(reflected, slot) - reflected;
        virtualPoint.xyz += moved - 2.0 * dot(moved, n) * n;
    }
    return previousUvOfPoint(uv, virtualPoint, prevW);
}
