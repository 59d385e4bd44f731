// Level 0 of the depth hierarchy (hiz.h) is the depth buffer itself: 1 − depth on screen, empty in
// the padding beyond it. Read by the march (ssr_hiz.comp); the build reads the depth buffer in 2×2
// gathers of its own. Include after common/bindings.glsl (frame constants) and hiz/hiz.h.

// The depth-buffer sample under a level-0 texel: 0 (as sky) in the padding, which is not fetched.
// Its hierarchy value is hizFromReverseZ of it (hizFromReverseZ(0) is kHizEmpty, exactly).
float hizLevel0Depth(sampler2D depth, ivec2 p) { return all(lessThan(p, ivec2(frame.screenSize))) ? texelFetch(depth, p, 0).r : 0.0; }
