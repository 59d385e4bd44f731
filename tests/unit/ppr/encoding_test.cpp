// The intermediate-buffer encoding: the same header the projection and reflection shaders compile.
#include "ppr_common/encoding.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace ppr::gpu;

namespace {

constexpr float kPi = 3.14159265f;

// The offset the decoder restores, with the fraction flip undone (mirroring is its own inverse).
glm::vec2 restored(const PprDecoded& d, glm::vec2 original) { return d.whole + pprMirrorAlong(d.fraction, original); }

// Dense sweep of offsets: `directions` directions, off the axes, × lengths from 0.3 px up to
// `longest` (0.173 px apart below 40 px, then 1.3 % apart).
template <class Visit>
void forEachSweptOffset(int directions, float longest, Visit&& visit) {
    for (int a = 0; a < directions; ++a) {
        const float angle = 2.0f * kPi * (a + 0.37f) / float(directions);
        const glm::vec2 dir(std::cos(angle), std::sin(angle));
        for (float len = 0.3f; len < longest; len = len < 40.0f ? len + 0.173f : len * 1.013f) visit(dir * len);
    }
}

}  // namespace

TEST(PprEncoding, RoundTripWithinOneEighthPixelInEveryDirectionAndLength) {
    // 720 directions × lengths to the 12-bit limit along the axis.
    float worst = 0.0f;
    int checked = 0;
    forEachSweptOffset(720, 2800.0f, [&](glm::vec2 offset) {
        uint v = 0;
        if (!pprEncode(offset, v)) {
            // Only offsets beyond the X range may be refused; Y up to 4095 always fits.
            EXPECT_GT(std::min(std::abs(offset.x), std::abs(offset.y)), 2047.0f) << offset.x << "," << offset.y;
            return;
        }
        const PprDecoded d = pprDecode(v);
        ASSERT_TRUE(d.valid);
        const float err = glm::length(restored(d, offset) - offset);
        worst = std::max(worst, err);
        ASSERT_LE(err, 0.125f + 1e-4f) << "offset " << offset.x << "," << offset.y;
        ++checked;
    });
    EXPECT_GT(checked, 300000);
    EXPECT_GT(worst, 0.05f);  // the sweep does exercise the quantisation
}

TEST(PprEncoding, WholePartIsExactAndBasisFollowsOrientation) {
    for (int y = -300; y <= 300; y += 7)
        for (int x = -300; x <= 300; x += 11) {
            if (x == 0 && y == 0) continue;
            const glm::vec2 offset(x + 0.2f, y - 0.3f);
            uint v = 0;
            ASSERT_TRUE(pprEncode(offset, v));
            const PprDecoded d = pprDecode(v);
            EXPECT_EQ(d.whole, glm::floor(offset + 0.5f));
            EXPECT_EQ(v & 3u, pprBasisIndex(offset));
            // Y, the most significant field, is the length along the chosen axis.
            EXPECT_EQ(v >> 20u, static_cast<uint>(std::max(std::abs(std::floor(offset.x + 0.5f)), std::abs(std::floor(offset.y + 0.5f)))));
        }
}

TEST(PprEncoding, ShorterOffsetToTheSameTargetEncodesSmallerInEveryBasis) {
    // Sources reflected onto one target lie on one screen-space line through it, so their offsets
    // are parallel. Whenever the rounded length along the axis differs, the closer source (shorter
    // offset) must win imageAtomicMin: it has to encode to the smaller value.
    int pairs = 0;
    for (int a = 0; a < 360; ++a) {
        const float angle = 2.0f * kPi * (a + 0.5f) / 360.0f;
        const glm::vec2 dir(std::cos(angle), std::sin(angle));
        const uint basis = pprBasisIndex(dir);
        for (float l1 = 0.5f; l1 < 1500.0f; l1 = l1 * 1.21f + 0.31f)
            for (float extra : {0.05f, 0.4f, 0.9f, 1.45f, 3.7f, 40.0f, 900.0f}) {
                const glm::vec2 near = dir * l1, far = dir * (l1 + extra);
                uint vn = 0, vf = 0;
                if (!pprEncode(near, vn) || !pprEncode(far, vf)) continue;
                ASSERT_EQ(vn & 3u, vf & 3u);  // same direction → same basis
                const float yNear = std::floor(pprToBasis(near, basis).y + 0.5f);
                const float yFar = std::floor(pprToBasis(far, basis).y + 0.5f);
                if (yNear < yFar) {
                    EXPECT_LT(vn, vf) << "basis " << basis << " lengths " << l1 << " < " << l1 + extra;
                    ++pairs;
                }
                // One axis pixel apart or more always orders correctly, whatever the fractions.
                if (extra * std::max(std::abs(dir.x), std::abs(dir.y)) >= 1.0f) {
                    EXPECT_LT(vn, vf);
                }
            }
    }
    EXPECT_GT(pairs, 10000);
    // Every basis was exercised.
    for (uint b = 0; b < 4; ++b) {
        uint v = 0;
        ASSERT_TRUE(pprEncode(pprBasisAxis(b) * 10.0f, v));
        EXPECT_EQ(v & 3u, b);
    }
}

TEST(PprEncoding, ClearValueNeverDecodesAndIsNeverProduced) {
    const PprDecoded d = pprDecode(kPprClearValue);
    EXPECT_FALSE(d.valid);
    EXPECT_EQ(d.whole, glm::vec2(0.0f));
    EXPECT_EQ(d.fraction, glm::vec2(0.0f));
    // The one offset whose bit pattern would be all ones (Y 4095, X 2047, fractions 7, basis 3) is refused.
    const glm::vec2 corner(-2047.0f - 0.01f, -4095.0f + 0.3f);  // basis 3 (−y), X = +2047 across it
    uint v = 0;
    EXPECT_EQ(pprBasisIndex(corner), 3u);
    EXPECT_FALSE(pprEncode(corner, v) && v == kPprClearValue);
    // Sweep the extreme corner region in every basis: no encodable offset yields the clear value.
    for (uint b = 0; b < 4; ++b)
        for (float y = 4093.6f; y < 4095.5f; y += 0.11f)
            for (float x = 2045.6f; x < 2047.5f; x += 0.11f)
                for (float sx : {-1.0f, 1.0f}) {
                    const glm::vec2 o = pprFromBasis(glm::vec2(x * sx, y), b);
                    uint e = 0;
                    if (pprEncode(o, e)) {
                        EXPECT_NE(e, kPprClearValue);
                        EXPECT_TRUE(pprDecode(e).valid);
                    } else {
                        EXPECT_EQ(e, kPprClearValue);
                    }
                }
}

TEST(PprEncoding, OffsetsBeyondTheTwelveBitRangeAreRefusedNotWrapped) {
    uint v = 0;
    EXPECT_FALSE(pprEncode(glm::vec2(4096.0f, 0.0f), v));        // Y integer 4096
    EXPECT_FALSE(pprEncode(glm::vec2(3000.0f, 2100.0f), v));     // X integer 2100 across the +x axis
    EXPECT_FALSE(pprEncode(glm::vec2(-2049.0f, -3000.0f), v));   // X below −2048
    EXPECT_TRUE(pprEncode(glm::vec2(4095.0f, 2047.0f), v));      // the largest representable
    EXPECT_EQ(pprDecode(v).whole, glm::vec2(4095.0f, 2047.0f));
    EXPECT_TRUE(pprEncode(glm::vec2(-4095.0f, -2047.4f), v));
    EXPECT_EQ(pprDecode(v).whole, glm::vec2(-4095.0f, -2047.0f));
}

TEST(PprEncoding, FractionIsMirroredAlongTheOffset) {
    // Along the offset the fractional part changes sign; across it, it is kept.
    uint v = 0;
    ASSERT_TRUE(pprEncode(glm::vec2(10.3f, 0.0f), v));
    PprDecoded d = pprDecode(v);
    EXPECT_NEAR(d.fraction.x, -0.3f, 0.09f);
    EXPECT_NEAR(d.fraction.y, 0.0f, 0.09f);
    ASSERT_TRUE(pprEncode(glm::vec2(10.0f, 0.3f), v));
    d = pprDecode(v);
    EXPECT_NEAR(d.fraction.y, 0.3f, 0.09f);
}

// The reflection pass settles most "significantly shorter" tests on the encoded integer parts
// (ppr_resolve.glsl, significantlyNearer): they must be the decoded whole offset in the value's
// basis, and parts within 2 per axis must mean offsets under 4.6 px apart.
TEST(PprEncoding, EncodedWholePartsAreTheDecodedOnesAndBoundTheDistance) {
    uint32_t checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const float angle = float(i) * 0.7371f, length = 0.3f + float(i % 997) * 0.9f;
        const glm::vec2 offset(std::cos(angle) * length, std::sin(angle) * length);
        uint32_t value = 0;
        if (!pprEncode(offset, value)) continue;
        const PprDecoded d = pprDecode(value);
        const uint32_t basis = pprEncodedBasis(value);
        EXPECT_EQ(basis, pprBasisIndex(offset));
        const glm::vec2 inBasis = pprToBasis(d.whole, basis);
        EXPECT_EQ(pprEncodedWhole(value), glm::ivec2(int(inBasis.x) + kPprXBias, int(inBasis.y)));
        // A neighbour up to 2 integer steps away on each axis, same basis when it keeps it.
        const glm::vec2 nudge(float(i % 5 - 2) + 0.37f * float(i % 3), float((i / 5) % 5 - 2) - 0.29f * float(i % 2));
        uint32_t other = 0;
        if (!pprEncode(offset + nudge, other) || pprEncodedBasis(other) != basis) continue;
        if (glm::all(glm::lessThanEqual(glm::abs(pprEncodedWhole(other) - pprEncodedWhole(value)), glm::ivec2(2)))) {
            const PprDecoded e = pprDecode(other);
            EXPECT_LT(glm::distance(d.whole + d.fraction, e.whole + e.fraction), 4.6f) << i;
            ++checked;
        }
    }
    EXPECT_GT(checked, 1000u);
}

// The projection's magnified cells (splat=1) write texel centres from points between source pixels:
// their fraction is stored as is, so whole + fraction is the offset itself (no mirroring to undo),
// and they order against the mirrored values as any other offset of that length.
TEST(PprEncoding, UnmirroredFractionDecodesToTheOffsetItself) {
    float worst = 0.0f;
    forEachSweptOffset(360, 600.0f, [&](glm::vec2 offset) {
        uint unmirrored = 0, mirrored = 0;
        ASSERT_TRUE(pprEncodeUnmirrored(offset, unmirrored));
        ASSERT_TRUE(pprEncode(offset, mirrored));
        const PprDecoded d = pprDecode(unmirrored);
        const float err = glm::length(d.whole + d.fraction - offset);
        worst = std::max(worst, err);
        ASSERT_LE(err, 0.125f + 1e-4f) << offset.x << "," << offset.y;
        EXPECT_EQ(d.whole, pprDecode(mirrored).whole);
        EXPECT_EQ(unmirrored >> 20u, mirrored >> 20u);  // the same integer length along the axis
    });
    EXPECT_GT(worst, 0.05f);
}
