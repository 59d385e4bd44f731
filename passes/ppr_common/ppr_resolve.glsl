// PPR's reflection resolve, shared by the screen-space reflection pass (ppr_reflect.comp) and the
// glass atlas's (glass_reflect.comp): decode the offset stored at a texel, patch holes from the
// neighbour with the shortest offset, sample the lit scene filtered (over the pixel's footprint where
// the reflection is minified) and unfiltered, and reduce the colour bleeding of the filtered sample.
//
// The includer provides `uint fetchValue(ivec2 texel)` (kPprClearValue outside its buffer) and the
// samplers `sceneLinear` / `scenePoint` (the lit scene, bilinear and point). A texel covers
// `pixelsPerTexel` screen pixels (1 for the screen-sized buffer; more in a scaled-down atlas region);
// the stored offsets are always in screen pixels.
#include "ppr_common/encoding.h"
#include "ppr_reflect/ppr_reflect.h"

vec2 fullOffset(uint v) {
    PprDecoded d = pprDecode(v);
    return d.whole + d.fraction;
}

vec3 rgbToYCoCg(vec3 c) { return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b); }
vec3 yCoCgToRgb(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// Keep the filtered colour unless it strays perceptually far from the point sample: luma and
// (luma-normalised) chroma are pulled towards the point sample separately, by how far apart they are
// (times `strength`: 1, less where the filtered colour averages a minified footprint).
vec3 reduceColorBleeding(vec3 filtered, vec3 unfiltered, float strength) {
    float exposure = frame.lightColor.w;  // compare as displayed, not in raw HDR units
    vec3 f = rgbToYCoCg(filtered * exposure), u = rgbToYCoCg(unfiltered * exposure);
    f.yz /= max(f.x, 1e-4);
    u.yz /= max(u.x, 1e-4);
    float lumaWeight = clamp(3.0 * strength * abs(f.x - u.x), 0.0, 1.0);
    float chromaWeight = clamp(1.4 * strength * length(f.yz - u.yz), 0.0, 1.0);
    float y = mix(f.x, u.x, lumaWeight);
    vec2 coCg = mix(f.yz, u.yz, chromaWeight) * y;
    return max(yCoCgToRgb(vec3(y, coCg)), vec3(0.0)) / exposure;
}

// The depth-aware hole rule (holes=1). The slides' rule grows a near object by a pixel into whatever
// lies behind it: at its silhouette, a neighbour's shorter offset looks like a first-layer hole.
// Here a texel with data takes a neighbour's only when the nearer layer encloses it: both its
// horizontal or both its vertical neighbours hold a significantly (kPprHoleMinDistance) shorter
// offset. An empty texel looks up to kPprHoleReach texels each way (holes in a magnified layer are
// that wide) and takes the nearer side of the direction whose two sides agree best, i.e. the layer it
// lies inside; with no direction holding data on both sides, the nearest layer around it, as the
// slides do. The diagonals were measured too: slower, and no better (docs/quality.md).
// A nearer layer magnified several times lands its samples 2-3 texels apart, and the far layer shows
// in the gaps with only one side enclosed; see enclosedHoleSource for how those texels are told from
// an outline and filled between the layer's samples.
struct PprSide {
    uint value;    // the shortest offset within reach on this side (kPprClearValue: none)
    ivec2 texel;
};

PprSide nearestOnSide(ivec2 texel, ivec2 step, int reach) {
    PprSide side;
    side.value = kPprClearValue;
    side.texel = texel;
    for (int k = 1; k <= reach; ++k) {
        uint v = fetchValue(texel + step * k);
        if (v < side.value) {
            side.value = v;
            side.texel = texel + step * k;
        }
    }
    return side;
}

// Whether two encoded offsets lie within 2 px of each other per axis, read without decoding: in one
// basis, integer parts within 2 of each other are under 4.6 px apart.
bool closeOffsets(uint v, uint v0) {
    return pprEncodedBasis(v) == pprEncodedBasis(v0) && all(lessThanEqual(abs(pprEncodedWhole(v) - pprEncodedWhole(v0)), ivec2(2)));
}

// Whether offset `v` is significantly (kPprHoleMinDistance) shorter than this texel's own `v0`
// (decoded: `own`). Neighbours within one layer differ by a pixel or two, so most calls are settled
// on the encoded values (closeOffsets), without decoding.
bool significantlyNearer(uint v, uint v0, vec2 own) {
    if (v >= v0 || closeOffsets(v, v0)) return false;
    return distance(own, fullOffset(v)) > kPprHoleMinDistance;
}

// Where a texel's reflection comes from: a texel's data (its own or a neighbour's), or a position
// between two samples of one magnified layer.
struct PprHoleChoice {
    ivec2 texel;       // the texel whose data is used
    bool between;      // a magnified layer's gap: sample at `source` instead
    vec2 source;       // screen position (pixels) of the filtered sample when `between`
    uvec4 around;      // a texel with data: its neighbours' values at +x, -x, +y, -y (for pprFootprint)
};

// The screen position a texel's data reflects to its centre: its filtered source.
vec2 filteredSource(ivec2 texel, uint v, ivec2 origin, vec2 originCentre, float pixelsPerTexel) {
    return originCentre + vec2(texel - origin) * pixelsPerTexel - fullOffset(v);
}

PprHoleChoice enclosedHoleSource(ivec2 texel, uint v0, vec2 screenCentre, float pixelsPerTexel) {
    const ivec2 directions[2] = ivec2[2](ivec2(1, 0), ivec2(0, 1));
    bool empty = v0 == kPprClearValue;
    vec2 own = empty ? vec2(0.0) : fullOffset(v0);
    PprHoleChoice choice;
    choice.texel = texel;
    choice.between = false;
    choice.source = screenCentre;
    choice.around = uvec4(kPprClearValue);
    uint best = v0;
    float bestSpread = 3.4e38;  // empty: how far apart the chosen direction's two sides are
    uint anyBest = kPprClearValue;
    ivec2 anyTexel = texel;
    for (int k = 0; k < 2; ++k) {
        int reach = empty ? kPprHoleReach : 1;
        PprSide a = nearestOnSide(texel, directions[k], reach), b = nearestOnSide(texel, -directions[k], reach);
        PprSide nearer = a.value < b.value ? a : b;
        if (empty) {
            if (nearer.value < anyBest) {
                anyBest = nearer.value;
                anyTexel = nearer.texel;
            }
            if (a.value == kPprClearValue || b.value == kPprClearValue) continue;
            float spread = distance(fullOffset(a.value), fullOffset(b.value));
            if (spread < bestSpread) {
                bestSpread = spread;
                best = nearer.value;
                choice.texel = nearer.texel;
            }
            continue;
        }
        if (k == 0) choice.around.xy = uvec2(a.value, b.value);  // reach 1: the adjacent texels
        else choice.around.zw = uvec2(a.value, b.value);
        bool nearA = significantlyNearer(a.value, v0, own), nearB = significantlyNearer(b.value, v0, own);
        if (nearA && nearB) {
            if (nearer.value < best) {
                best = nearer.value;
                choice.texel = nearer.texel;
                choice.between = false;
            }
            continue;
        }
        // A nearer layer on one side only: an outline, or a layer magnified so much that its samples
        // land kPprHoleMagnifiedReach texels apart with the far layer showing between them. It is the
        // latter when the nearer layer lies further along on the other side too and the two samples
        // come from neighbouring pixels of the main view: one surface, so this texel lies on it.
        if (nearA == nearB || choice.between || best != v0) continue;
        PprSide near = nearA ? a : b;
        ivec2 away = nearA ? -directions[k] : directions[k];
        PprSide far = nearestOnSide(texel + away, away, kPprHoleMagnifiedReach - 1);
        if (!significantlyNearer(far.value, v0, own)) continue;
        vec2 nearSource = filteredSource(near.texel, near.value, texel, screenCentre, pixelsPerTexel);
        vec2 farSource = filteredSource(far.texel, far.value, texel, screenCentre, pixelsPerTexel);
        if (any(greaterThan(abs(floor(nearSource) - floor(farSource)), vec2(1.0)))) continue;
        float t = 1.0 / float(1 + abs(dot(vec2(far.texel - texel), vec2(away))));  // 1 / (texels from near to far)
        choice.texel = near.texel;
        choice.between = true;
        choice.source = mix(nearSource, farSource, t);
    }
    if (empty && best == kPprClearValue) choice.texel = anyTexel;  // no two sides to compare: the nearest layer around
    return choice;
}

// holes=1, a screen texel with its own data: where its filtered sample lies and how far the target
// pixel reaches in the source, from the local source → target map. Each value names a source pixel
// centre (the texel centre minus the whole offset) and, by its fraction, where that source landed
// in the texel (the fraction un-mirrored); an adjacent texel of the same layer per axis gives the
// map's two columns. The slides' mirrored fraction assumes a unit mirror map; a reflection seen
// obliquely is minified several times (the floor in the wall mirror: 8 source pixels per target
// row), where it misplaces the sample by up to a few source pixels and a single bilinear tap
// aliases thin lines. Per axis the neighbour whose source lies nearer is taken; kPprFootprintMaxStep
// or more away, it is another layer. False: the slides' sample.
struct PprFootprint {
    vec2 position;         // screen position (pixels) of the filtered sample
    mat2 sourcePerTarget;  // source pixels per target pixel: columns along target x and y
};

// One axis of the map: of the adjacent texels `plus` and `minus` along `axis`, the one whose source
// lies nearer (under kPprFootprintMaxStep); the steps are per target pixel along +axis.
bool footprintStep(uint plus, uint minus, vec2 axis, PprDecoded own, vec2 ownLanding, out vec2 sourceStep, out vec2 targetStep) {
    float nearest = kPprFootprintMaxStep;
    bool found = false;
    for (int side = 0; side < 2; ++side) {
        uint v = side == 0 ? plus : minus;
        if (v == kPprClearValue) continue;
        float sign = side == 0 ? 1.0 : -1.0;
        PprDecoded n = pprDecode(v);
        vec2 step = axis * sign - n.whole + own.whole;
        if (length(step) >= nearest) continue;
        nearest = length(step);
        sourceStep = step * sign;
        targetStep = (axis * sign + pprMirrorAlong(n.fraction, n.whole + n.fraction) - ownLanding) * sign;
        found = true;
    }
    return found;
}

bool pprFootprint(PprDecoded own, uvec4 around, vec2 screenCentre, out PprFootprint footprint) {
    vec2 ownLanding = pprMirrorAlong(own.fraction, own.whole + own.fraction);  // where it landed, from the centre
    vec2 sourceX, targetX, sourceY, targetY;
    if (!footprintStep(around.x, around.y, vec2(1.0, 0.0), own, ownLanding, sourceX, targetX) ||
        !footprintStep(around.z, around.w, vec2(0.0, 1.0), own, ownLanding, sourceY, targetY))
        return false;
    mat2 targetSteps = mat2(targetX, targetY);
    if (abs(determinant(targetSteps)) < 0.05) return false;
    footprint.sourcePerTarget = mat2(sourceX, sourceY) * inverse(targetSteps);
    footprint.position = screenCentre - own.whole - footprint.sourcePerTarget * ownLanding;
    return true;
}

struct PprResolved {
    bool valid;
    vec3 color;           // pprResolve: the resolved colour (black where not valid); pprLocate: black
    ivec2 readTexel;      // the texel whose data was used (hole filling may pick a neighbour)
    vec2 source;          // screen position (pixels) of the point sample: where the reflected point is seen
    vec2 filtered;        // screen position of the filtered sample (minified: the centre of its two taps)
    vec2 halfStep;        // minified: the filtered sample's two taps lie ± this apart (0: one tap)
    float bleedStrength;  // how strongly anti-bleeding pulls toward the point sample
};

// Where a texel's reflection is sampled, without sampling it: the reflection pass replaces the colour
// of a normal-mapped pixel, and fetches the flat one only where it keeps it (pprColor).
PprResolved pprLocate(ivec2 texel, vec2 screenCentre, float pixelsPerTexel, uint flags) {
    PprResolved r;
    r.readTexel = texel;
    r.color = vec3(0.0);
    r.source = screenCentre;
    r.filtered = screenCentre;
    r.halfStep = vec2(0.0);
    r.bleedStrength = 1.0;
    uint v0 = fetchValue(texel);
    bool between = false;  // holes=1 inside a magnified layer: sample between two of its samples
    vec2 betweenSource = screenCentre;
    uvec4 around = uvec4(kPprClearValue);
    // Hole filling. holes=1: enclosedHoleSource. holes=slides: take the neighbour with the smallest
    // offset when this texel has no data, or when that neighbour's offset is significantly
    // (kPprHoleMinDistance) shorter — a hole in the first reflection layer; the slides' four neighbours.
    if ((flags & kPprHoleEnclosed) != 0u) {
        PprHoleChoice choice = enclosedHoleSource(texel, v0, screenCentre, pixelsPerTexel);
        r.readTexel = choice.texel;
        between = choice.between;
        betweenSource = choice.source;
        around = choice.around;
    } else if ((flags & kPprHoleFilling) != 0u) {
        const ivec2 n1 = ivec2(1, 0), n2 = ivec2(0, 1), n3 = ivec2(1, 1), n4 = ivec2(-1, 0);
        uint v1 = fetchValue(texel + n1), v2 = fetchValue(texel + n2), v3 = fetchValue(texel + n3), v4 = fetchValue(texel + n4);
        uint vmin = min(min(min(v0, v1), min(v2, v3)), v4);
        bool fill = v0 == kPprClearValue || distance(fullOffset(v0), fullOffset(vmin)) > kPprHoleMinDistance;
        if (fill && vmin != v0) {
            if (vmin == v1) r.readTexel = texel + n1;
            else if (vmin == v2) r.readTexel = texel + n2;
            else if (vmin == v3) r.readTexel = texel + n3;
            else r.readTexel = texel + n4;
        }
    }
    vec2 filteredAt = betweenSource, pointAt = floor(betweenSource) + 0.5;
    r.valid = between;
    PprDecoded d;
    if (!between) {
        d = pprDecode(fetchValue(r.readTexel));
        r.valid = d.valid;
        if (!d.valid) return r;

        // The offset as if this texel had the neighbour's data: the point sample repeats the
        // neighbour's source; the filtered one moves the source the mirrored way along the offset.
        vec2 offsetFiltered = d.whole + d.fraction;
        vec2 offsetPoint = d.whole;
        vec2 shift = vec2(r.readTexel - texel) * pixelsPerTexel;
        if (r.readTexel != texel) {
            vec2 dir = normalize(offsetFiltered);
            offsetPoint -= shift;
            offsetFiltered -= 2.0 * dir * dot(dir, shift);
        }
        filteredAt = screenCentre - offsetFiltered;
        pointAt = screenCentre - offsetPoint;
    }
    r.source = pointAt;
    r.filtered = filteredAt;
    if ((flags & kPprFiltering) == 0u) return r;
    // holes=1, where the reflection is minified (more than kPprFootprintMinStep source pixels per
    // target pixel): the filtered sample where the local map puts it, averaged over the target pixel's
    // footprint along its longer side (two bilinear taps a half footprint apart: a box filter, as the
    // reference's texture LOD blurs what it minifies). Anti-bleeding then pulls less towards the one
    // point sample, which stands for a smaller share of the footprint. Adjacent offsets within 2 px of
    // this one (closeOffsets) mean a map near 1:1 (a unit mirror changes the offset by 2 per pixel):
    // nothing minified, and the footprint's decoding is skipped.
    bool unitMap = (closeOffsets(around.x, v0) || around.x == kPprClearValue) && (closeOffsets(around.y, v0) || around.y == kPprClearValue) &&
                   (closeOffsets(around.z, v0) || around.z == kPprClearValue) && (closeOffsets(around.w, v0) || around.w == kPprClearValue);
    bool screenGrid = all(equal(screenCentre, vec2(texel) + 0.5));  // texels are screen pixels, not a scaled atlas region
    PprFootprint footprint;
    float reach = 0.0;
    if ((flags & kPprHoleEnclosed) != 0u && !between && r.readTexel == texel && screenGrid && !unitMap &&
        pprFootprint(d, around, screenCentre, footprint))
        reach = max(length(footprint.sourcePerTarget[0]), length(footprint.sourcePerTarget[1]));
    if (reach > kPprFootprintMinStep && reach < kPprFootprintMaxStep) {
        mat2 m = footprint.sourcePerTarget;
        r.halfStep = 0.25 * (length(m[0]) > length(m[1]) ? m[0] : m[1]);
        r.filtered = footprint.position;
        r.bleedStrength = inversesqrt(reach);
    }
    return r;
}

// The lit scene filtered at screen position `centre` (pixels): one bilinear tap, or where a minified
// footprint gives `halfStep`, the mean of two taps that far on either side (a box filter).
vec3 footprintSample(vec2 centre, vec2 halfStep) {
    if (halfStep == vec2(0.0)) return textureLod(sceneLinear, centre * frame.invScreenSize, 0.0).rgb;
    return 0.5 * (textureLod(sceneLinear, (centre + halfStep) * frame.invScreenSize, 0.0).rgb +
                  textureLod(sceneLinear, (centre - halfStep) * frame.invScreenSize, 0.0).rgb);
}

// The colour at a located texel (valid): the point sample, or the filtered one (two taps where
// minified) with anti-bleeding.
vec3 pprColor(PprResolved r, uint flags) {
    vec3 unfiltered = textureLod(scenePoint, r.source * frame.invScreenSize, 0.0).rgb;
    if ((flags & kPprFiltering) == 0u) return unfiltered;
    vec3 filtered = footprintSample(r.filtered, r.halfStep);
    return (flags & kPprAntiBleeding) != 0u ? reduceColorBleeding(filtered, unfiltered, r.bleedStrength) : filtered;
}

PprResolved pprResolve(ivec2 texel, vec2 screenCentre, float pixelsPerTexel, uint flags) {
    PprResolved r = pprLocate(texel, screenCentre, pixelsPerTexel, flags);
    if (r.valid) r.color = pprColor(r, flags);
    return r;
}
