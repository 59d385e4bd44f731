// A G-buffer pixel's motion slot (gbuffer.h: the material target's alpha; gpu/scene_data.h MotionData,
// 0 = still), from that target's texel. Needs gpu/scene_data.h.
uint motionSlotOf(vec4 material) { return uint(material.a * float(kMaxMovingDraws) + 0.5); }
