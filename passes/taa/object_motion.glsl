// Per-object motion of an animated scene's moving draws (gpu::MotionData), on top of taa_motion.glsl's
// camera reprojection. The includer declares `materialTex` (the G-buffer's material target, whose
// alpha holds the draw's motion slot) and `motions[]`, then includes this after taa_motion.glsl.
// A moving draw's point is carried to where it was last frame before the camera's reprojection;
// slot 0 (everything still) is the camera's reprojection alone.
#include "gbuffer/motion_slot.glsl"
uint motionSlotAt(ivec2 pix) { return motionSlotOf(texelFetch(materialTex, pix, 0)); }
vec2 previousUvMoving(vec2 uv, float depth, uint slot, out float prevW) {
    if (slot == 0u) return previousUv(uv, depth, prevW);
    return previousUvOfPoint(uv, motions[slot].toPrevious * worldOfPixel(uv, depth), prevW);
}
