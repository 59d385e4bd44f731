// PPR projection, splat=1 (ppr_project.h): the cells a magnified surface's pixels fill
// (docs/quality.md, "The splat"). Included by ppr_project.comp, which provides the bindings used here:
// `frame`, `pc` (PprProjectPush), `reflectors`, `depthTex`, `normalTex` and `intermediate`.
#include "ppr_common/encoding.h"
#include "ppr_project/ppr_project.h"

// splat=1 (ppr_project.h): where reflector r magnifies the surface at p, the pixel also writes the
// target pixels inside the cell between its landing and its right and lower neighbours' landings,
// each with the offset from the point of the source cell that maps to that pixel's centre, so the
// magnified surface covers what lies behind it instead of showing it between its samples.
void splatMagnified(ivec2 pix, vec3 p, vec3 surfaceNormal, uint reflector, vec3 mirrored, float facing, vec2 target) {
    vec3 eye = frame.cameraPos.xyz;
    // Target pixels per source pixel along the most stretched direction, estimated from what the
    // choice already knows (the mirrored eye is as far from p as the eye from p's mirror image):
    // the distance ratio times the ratio of the cosines to the mirrored eye and to the eye, squared
    // and multiplied out (every written pixel pays for this test; few pass it).
    vec3 toEye = eye - p;
    float eyeSquared = dot(toEye, toEye), mirroredSquared = dot(eye - mirrored, eye - mirrored);
    vec3 n = pc.facingOnly != 0u ? surfaceNormal : texelFetch(normalTex, pix, 0).xyz;
    if (facing > 1.5) {  // facing=0: not known yet
        vec3 planeNormal = reflectors[reflector].normal;
        facing = dot(n, toEye - 2.0 * dot(eye - reflectors[reflector].center, planeNormal) * planeNormal) * inversesqrt(mirroredSquared);
    }
    float towardEye = dot(n, toEye);
    float eyeCosSquared = max(towardEye * towardEye, kPprSplatMinCos * kPprSplatMinCos * eyeSquared);  // times eyeSquared
    if (eyeSquared * max(eyeCosSquared, facing * facing * eyeSquared) < kPprSplatMinStretch * kPprSplatMinStretch * mirroredSquared * eyeCosSquared)
        return;
    float toEyeLength = sqrt(eyeSquared), cosEye = sqrt(eyeCosSquared / eyeSquared);
    ReflectorData r = reflectors[reflector];
    float eyeHeight = dot(eye - r.center, r.normal);
    float reach = kPprSplatReach * 2.0 * toEyeLength / (abs(frame.proj[1][1]) * frame.screenSize.y * max(cosEye, 0.05));
    vec2 steps[2];  // where the right and the lower neighbour land, from this pixel's landing
    vec2 from = vec2(0.0), to = vec2(1.0);  // the part of the source cell filled, per axis
    for (int k = 0; k < 2; ++k) {
        ivec2 q = pix + ivec2(1 - k, k);
        vec2 uv = (vec2(q) + 0.5) * frame.invScreenSize;
        float depth = all(lessThan(q, ivec2(frame.screenSize))) ? texelFetch(depthTex, q, 0).r : 0.0;
        vec3 neighbour = depth > 0.0 ? worldFromDepth(uv, depth) : p;
        if (depth <= 0.0 || distance(neighbour, p) > reach || dot(normalize(texelFetch(normalTex, q, 0).xyz), n) < kPprSplatNormalCos) {
            // Not on this surface (its outline, seen as a sliver): the neighbour's ray on the pixel's
            // tangent plane, and only the pixel's own half of the cell on either side.
            vec3 ray = worldFromDepth(uv, 1.0) - eye;
            float across = dot(ray, n);
            if (abs(across) < 1e-6) return;
            neighbour = eye + ray * (dot(p - eye, n) / across);
            from[k] = -kPprSplatOutline;
            to[k] = kPprSplatOutline;
        }
        float height = dot(neighbour - r.center, r.normal);
        if (height <= kPprAboveEpsilon) return;
        vec3 mirrored = neighbour - 2.0 * height * r.normal;
        if (!reflectorContains(r, mix(eye, mirrored, eyeHeight / (eyeHeight + height)))) return;
        vec4 clip = frame.viewProj * vec4(mirrored, 1.0);
        if (clip.w <= 0.0) return;
        steps[k] = pixelFromClip(clip) - target;
        if (!(length(steps[k]) < kPprSplatMaxStep)) return;  // NaN too: the loop below stays within 32 x 32 pixels
    }
    mat2 cell = mat2(steps[0], steps[1]);
    if (!(abs(determinant(cell)) >= 1e-3)) return;
    mat2 toCell = inverse(cell);
    vec2 c00 = target + cell * from, c10 = target + cell * vec2(to.x, from.y), c01 = target + cell * vec2(from.x, to.y), c11 = target + cell * to;
    vec2 lo = min(min(c00, c10), min(c01, c11)), hi = max(max(c00, c10), max(c01, c11));
    ivec2 first = max(ivec2(ceil(lo - 0.5)), ivec2(0)), last = min(ivec2(floor(hi - 0.5)), ivec2(frame.screenSize) - 1);
    ivec2 landed = ivec2(target);
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) {
            vec2 centre = vec2(x, y) + 0.5;
            vec2 along = toCell * (centre - target);  // the source point, from this pixel's centre
            if (any(lessThan(along, from)) || any(greaterThanEqual(along, to)) || ivec2(x, y) == landed) continue;
            uint value;
            if (pprEncodeUnmirrored(centre - (vec2(pix) + 0.5 + along), value)) imageAtomicMin(intermediate, ivec2(x, y), value);
        }
}
