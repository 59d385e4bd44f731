// Level 0 of the depth hierarchy (hiz.h) is the depth buffer itself: 1 − depth on screen, empty in
// the padding beyond it. Shared by the build (level 1's edge quads) and the march. Include after
// common/bindings.glsl (frame constants) and hiz/hiz.h.
float hizLevel0(sampler2D depth, ivec2 p) {
    return all(lessThan(p, ivec2(frame.screenSize))) ? hizFromReverseZ(texelFetch(depth, p, 0).r) : kHizEmpty;
}
