// PPR intermediate-buffer encoding (Cichocki 2017, "Intermediate buffer layout"), compiled by both the
// shaders and the C++ unit tests. One 32-bit value per pixel, most → least significant bits:
//   12 bits  Y integer   offset length along the snapped basis axis (unsigned, 0..4095)
//    3 bits  Y fraction  (mirrored along the offset, so it is "flipped")
//   12 bits  X integer   offset across the axis (signed, biased by 2048: −2048..2047)
//    3 bits  X fraction
//    2 bits  basis index 0:+x 1:−x 2:+y 3:−y — the axis closest to the offset's direction
// Y sits in the top bits so that imageAtomicMin keeps the shortest offset, i.e. the reflected pixel
// closest to the reflector (offsets landing on one target are collinear, so a shorter offset has a
// smaller Y in any basis whose Y is positive). Ordering holds at pixel granularity: two offsets whose
// rounded Y differ always order correctly; within one integer Y the flipped fraction may reverse them,
// which is the price the slides pay for motion-stable filtering.
// The offset points from the reflected (source) pixel centre to the continuous target position; it is
// written at the target pixel. Fractions are mirrored along the offset direction because moving the
// sampling point across the reflector moves the source the mirrored way (stops filtered results
// swimming under motion); decoding returns the mirrored fraction, which the reflection pass uses as is.
// Deviation from the slides' listing: fractions are quantised with floor and decoded at bin centres
// (the listing rounds on encode and decodes at bin centres, a +1/16 bias); the error bound is 1/8 px.
#ifndef PPR_ENCODING_H
#define PPR_ENCODING_H
#include "shader/shared.h"

PPR_CONST(uint, kPprClearValue, 0xFFFFFFFFu)   // "no data"; never produced by pprEncode
PPR_CONST(uint, kPprFractionSteps, 8u)         // 3 fraction bits
PPR_CONST(int, kPprXBias, 2048)                // X integer stored as X + 2048 in 12 bits
PPR_CONST(int, kPprMaxYInteger, 4095)
PPR_CONST(uint, kPprMaxExtent, 4096u)          // largest width/height whose offsets fit (see README)
PPR_CONST(float, kPprFractionScale, 0.70710678f)  // mirrored fractions reach ±0.707 per axis

PPR_BEGIN
struct PprDecoded {
    vec2 whole;     // integer part of the offset, screen space
    vec2 fraction;  // mirrored fractional part, screen space
    bool valid;     // false for kPprClearValue
};

PPR_INLINE uint pprBasisIndex(vec2 offset) {
    if (abs(offset.x) >= abs(offset.y)) return offset.x >= 0.0f ? 0u : 1u;
    return offset.y >= 0.0f ? 2u : 3u;
}
PPR_INLINE vec2 pprBasisAxis(uint index) {
    if (index == 0u) return vec2(1.0f, 0.0f);
    if (index == 1u) return vec2(-1.0f, 0.0f);
    if (index == 2u) return vec2(0.0f, 1.0f);
    return vec2(0.0f, -1.0f);
}
// Screen space → (X across the axis, Y along it) and back; exact for integer vectors.
PPR_INLINE vec2 pprToBasis(vec2 v, uint index) {
    vec2 a = pprBasisAxis(index);
    return vec2(a.y * v.x - a.x * v.y, a.x * v.x + a.y * v.y);
}
PPR_INLINE vec2 pprFromBasis(vec2 xy, uint index) {
    vec2 a = pprBasisAxis(index);
    return xy.x * vec2(a.y, -a.x) + xy.y * a;
}
// Reflects v about the line perpendicular to `direction` (negates v's component along it).
PPR_INLINE vec2 pprMirrorAlong(vec2 v, vec2 direction) {
    float len = length(direction);
    if (len <= 0.0f) return v;
    vec2 d = direction / len;
    return v - 2.0f * d * dot(d, v);
}
PPR_INLINE uint pprQuantizeFraction(float f) {  // f in [−0.707, 0.707] → 0..7
    float unit = clamp(f * kPprFractionScale + 0.5f, 0.0f, 1.0f);
    return min(uint(unit * float(kPprFractionSteps)), kPprFractionSteps - 1u);
}
PPR_INLINE float pprDequantizeFraction(uint q) {
    return ((float(q) + 0.5f) / float(kPprFractionSteps) - 0.5f) / kPprFractionScale;
}

// Packs an offset's rounded whole part and the fraction to store (decoded as is) in the basis chosen
// by `offset`. False (value = kPprClearValue) when the whole part does not fit the 12-bit integers.
PPR_INLINE bool pprEncodeParts(vec2 offset, vec2 whole, vec2 storedFraction, PPR_OUT(uint) value) {
    value = kPprClearValue;
    uint basis = pprBasisIndex(offset);
    vec2 w = pprToBasis(whole, basis);
    vec2 f = pprToBasis(storedFraction, basis);
    if (w.y < 0.0f || w.y > float(kPprMaxYInteger) || w.x < float(-kPprXBias) || w.x > float(kPprXBias - 1)) return false;
    uint y = uint(w.y) * kPprFractionSteps + pprQuantizeFraction(f.y);
    uint x = uint(int(w.x) + kPprXBias) * kPprFractionSteps + pprQuantizeFraction(f.x);
    uint packed = (((y << 15u) | x) << 2u) | basis;
    if (packed == kPprClearValue) return false;  // only Y=4095, X=2047, both fractions 7, basis 3
    value = packed;
    return true;
}

// Encodes a screen-space offset, its fraction mirrored (above). Returns false (value =
// kPprClearValue) when it does not fit the 12-bit integer parts; callers drop such writes rather than
// let them wrap.
PPR_INLINE bool pprEncode(vec2 offset, PPR_OUT(uint) value) {
    vec2 whole = floor(offset + 0.5f);
    return pprEncodeParts(offset, whole, pprMirrorAlong(offset - whole, offset), value);
}

// Encodes an offset whose fraction is stored unmirrored: the decoded whole + fraction is the offset
// itself (to the 1/8 px quantisation), so the filtered sample lies exactly `offset` from the texel
// centre. For a texel written at its centre from a point between source pixels (ppr_project's
// magnified cells), where there is no landing to mirror.
PPR_INLINE bool pprEncodeUnmirrored(vec2 offset, PPR_OUT(uint) value) {
    vec2 whole = floor(offset + 0.5f);
    return pprEncodeParts(offset, whole, offset - whole, value);
}

// The integer parts of an encoded value in its own basis (X across the axis, biased; Y along it)
// and the basis, read without decoding. Two values in one basis whose integer parts differ by at
// most 2 per axis are less than 4.6 px apart (the fractions add at most 1.24 per axis).
PPR_INLINE ivec2 pprEncodedWhole(uint value) { return ivec2(int((value >> 5u) & 0xFFFu), int(value >> 20u)); }
PPR_INLINE uint pprEncodedBasis(uint value) { return value & 3u; }

PPR_INLINE PprDecoded pprDecode(uint value) {
    PprDecoded d;
    d.whole = vec2(0.0f);
    d.fraction = vec2(0.0f);
    d.valid = value != kPprClearValue;
    if (!d.valid) return d;
    uint basis = value & 3u;
    uint x = (value >> 2u) & 0x7FFFu;
    uint y = value >> 17u;
    vec2 w = vec2(float(int(x / kPprFractionSteps) - kPprXBias), float(y / kPprFractionSteps));
    vec2 f = vec2(pprDequantizeFraction(x % kPprFractionSteps), pprDequantizeFraction(y % kPprFractionSteps));
    d.whole = pprFromBasis(w, basis);
    d.fraction = pprFromBasis(f, basis);
    return d;
}
PPR_END

#endif
