// PPR's normal-map approximation (--set normalmap=approx|raymarch, normal_refine=0|1|walk), included
// by the reflection pass (ppr_reflect.comp): where a normal-mapped pixel's reflected ray meets what
// it reflects, from the flat reflection's point. The includer provides `depthTex` (reverse-Z depth),
// the push constants `pc` (PprReflectPush) and `projectToScreen`.

// Whether the point `t` along the ray from `surface` is on screen and not behind the depth buffer.
bool visibleAlongRay(vec3 surface, vec3 dir, float t, out vec2 pixel, out bool onScreen) {
    float w;
    onScreen = projectToScreen(surface + dir * t, pixel, w);
    if (!onScreen) return false;
    float d = texelFetch(depthTex, ivec2(pixel), 0).r;
    return w <= (d > 0.0 ? frame.cameraPos.w / d : 1e30) * 1.001;  // in front of (or on) what the camera sees
}

// The world position the depth buffer shows at pixel `p`.
vec3 shownPoint(ivec2 p) { return worldOfPixel(p, texelFetch(depthTex, p, 0).r); }

// The plane of the surface shown at pixel `p` (world position `shown`): its normal from the positions
// shown there and at the next pixel across and down (the previous one on the screen's last column or
// row), turned toward the camera. Not the G-buffer normal: a normal map (the tiles' bevels) tilts that
// away from the surface's plane, and the crossing with a tilted plane lands beside the true one.
vec3 depthPlaneNormal(ivec2 p, vec3 shown) {
    ivec2 last = ivec2(frame.screenSize) - 1;
    vec3 across = p.x < last.x ? shownPoint(p + ivec2(1, 0)) - shown : shown - shownPoint(p - ivec2(1, 0));
    vec3 down = p.y < last.y ? shownPoint(p + ivec2(0, 1)) - shown : shown - shownPoint(p - ivec2(0, 1));
    vec3 n = normalize(cross(across, down));
    return dot(n, frame.cameraPos.xyz - shown) < 0.0 ? -n : n;
}

// normal_refine=1: the mapped ray meets the surface its flat reflection sees (`seenPoint`, at pixel
// `seenPix`) where it crosses that surface's plane (depthPlaneNormal). The crossing is taken when the
// depth buffer shows that plane at its pixel (within kPprNormalPlaneTolerance of the view distance):
// the ray ends on that surface. Otherwise the plane of the surface shown there is tried,
// kPprNormalPlaneGuesses planes in all. Three depth reads a plane, where a march toward the crossing
// reads one a step and ends within a step of it: on the flat faces most reflected points lie on, the
// plane's crossing is the hit. The tests are written to fail on NaN (a plane read off the sky).
bool surfacePlaneHit(vec3 surface, vec3 dir, float reach, ivec2 seenPix, vec3 seenPoint, out vec2 hitPixel) {
    for (uint k = 0u; k < kPprNormalPlaneGuesses; ++k) {
        vec3 planeNormal = depthPlaneNormal(seenPix, seenPoint);
        float facing = dot(dir, planeNormal);
        if (!(facing < -kPprNormalPlaneMinFacing)) return false;  // along the plane, or meeting its back
        float t = dot(seenPoint - surface, planeNormal) / facing;
        float w;
        if (!(t > 0.0 && t < reach) || !projectToScreen(surface + dir * t, hitPixel, w)) return false;
        ivec2 shownPix = ivec2(hitPixel);
        float depth = texelFetch(depthTex, shownPix, 0).r;
        if (depth <= 0.0) return false;
        vec3 shown = worldOfPixel(shownPix, depth);
        if (abs(dot(shown - seenPoint, planeNormal)) < kPprNormalPlaneTolerance * frame.cameraPos.w / depth) return true;
        seenPix = shownPix;
        seenPoint = shown;
    }
    return false;
}

// normal_refine=walk (the default until 2026-12-06): from the taken tap at `t`, the search for where
// the ray crosses the depth buffer. A tap that follows a hidden one moves by bisection to the
// crossing; an approximated point (tap 0) that is not hidden first walks on along the ray to find it.
void walkToCrossing(vec3 surface, vec3 dir, float dist, float step, float t, bool approximated, bool previousHidden, inout vec2 hitPixel) {
    float visible = t, hidden = t + step;
    bool onScreen;
    if (approximated) {
        // Along the mapped ray, what it reflects lies farther than the flat distance. Walk on in
        // short steps; the last point still in front is the nearest known to the hit, crossing found
        // or not.
        float ahead = step * kPprNormalAheadStep;
        for (uint j = 1u; j <= kPprNormalAheadSteps; ++j) {
            vec2 p;
            float next = dist + ahead * float(j);
            if (visibleAlongRay(surface, dir, next, p, onScreen)) {
                visible = next;
                hitPixel = p;
                continue;
            }
            if (onScreen) {
                previousHidden = true;
                hidden = next;
            }
            break;
        }
    }
    // The ray passed behind the depth buffer between the last visible point and the hidden one after
    // it: the taken point moves toward that crossing, where the ray meets what it reflects, not the
    // free space before it.
    if (!previousHidden) return;
    for (uint i = 0u; i < kPprNormalRefineSteps; ++i) {
        float mid = 0.5 * (visible + hidden);
        vec2 p;
        if (visibleAlongRay(surface, dir, mid, p, onScreen)) {
            visible = mid;
            hitPixel = p;
        } else {
            hidden = mid;
        }
    }
}

// The bonus slides' normal-map approximation. The flat reflection found the reflected point at
// `flatSource` (pixels); its distance from the surface point stands for the distance along the ray
// reflected about the normal-mapped normal. approx: the point that far along that ray, projected.
// raymarch: kPprNormalTaps points from there back toward the reflecting pixel; the first one not
// hidden behind the depth buffer is taken (an approximated point behind a nearer object would fetch
// that object: the disocclusion the slides show). normal_refine=1 tries the surfaces' planes first
// (surfacePlaneHit), the taps where none is shown there; normal_refine=walk searches from the
// taken tap (walkToCrossing). False: keep the flat reflection.
bool normalMappedHit(vec3 surface, vec3 dir, vec2 flatSource, out vec2 hitPixel) {
    ivec2 src = clamp(ivec2(flatSource), ivec2(0), ivec2(frame.screenSize) - 1);
    float srcDepth = texelFetch(depthTex, src, 0).r;
    if (srcDepth <= 0.0) return false;
    vec3 flatPoint = worldOfPixel(src, srcDepth);
    float dist = distance(surface, flatPoint);
    float w;
    if ((pc.flags & kPprNormalRaymarch) == 0u) return projectToScreen(surface + dir * dist, hitPixel, w);
    bool walk = (pc.flags & kPprNormalWalk) != 0u;
    if (!walk && (pc.flags & kPprNormalRefine) != 0u && surfacePlaneHit(surface, dir, dist * kPprNormalPlaneReach, src, flatPoint, hitPixel))
        return true;
    float step = dist / float(kPprNormalTaps);
    bool previousHidden = false;  // the point farther along the ray lies on screen behind the depth buffer
    for (uint k = 0u; k < kPprNormalTaps; ++k) {
        float t = dist - step * float(k);
        bool onScreen;
        if (!visibleAlongRay(surface, dir, t, hitPixel, onScreen)) {
            previousHidden = onScreen;
            continue;
        }
        if (walk) walkToCrossing(surface, dir, dist, step, t, k == 0u, previousHidden, hitPixel);
        return true;
    }
    return false;
}
