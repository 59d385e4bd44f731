// The `stress:N` scene: spec parsing, tile/reflector layout invariants, mesh sanity, and the
// reflective screen fractions of its sweep cameras (CPU ray cast, so no GPU is needed).
#include "scene/stress_scene.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>

using namespace ppr::scene;

namespace {

glm::vec3 worldVertex(const Scene& s, const DrawItem& d, uint32_t i) {
    const Mesh& m = s.meshes[d.mesh];
    const Vertex& v = s.vertices[size_t(m.vertexOffset) + s.indices[m.firstIndex + i]];
    return glm::vec3(d.world * glm::vec4(v.position, 1.0f));
}

float tileArea(const Reflector& r) { return 4.0f * r.halfExtents.x * r.halfExtents.y; }

std::string parseError(const std::string& spec) {
    try {
        parseStressSpec(spec);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

// Möller–Trumbore; distance along `dir` or +inf.
float hitTriangle(const glm::vec3& o, const glm::vec3& dir, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) return std::numeric_limits<float>::infinity();
    const glm::vec3 t = o - a;
    const float u = glm::dot(t, p) / det;
    const glm::vec3 q = glm::cross(t, e1);
    const float v = glm::dot(dir, q) / det;
    const float dist = glm::dot(e2, q) / det;
    return (u >= 0 && v >= 0 && u + v <= 1 && dist > 0) ? dist : std::numeric_limits<float>::infinity();
}

// Share of a 16:9 image (w x h rays through pixel centres) whose first hit is a mirror tile: the
// same quantity as counting debug=reflectors pixels in a render.
float reflectiveFraction(const Scene& s, const CameraPose& pose, int w, int h) {
    const float yaw = glm::radians(pose.yawDeg), tanHalf = std::tan(glm::radians(pose.fovYDeg) * 0.5f);
    const glm::vec3 f = viewDirection(pose.yawDeg, pose.pitchDeg), r{std::cos(yaw), 0, std::sin(yaw)}, u = glm::cross(r, f);
    int onTile = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float nx = (2.0f * (float(x) + 0.5f) / float(w) - 1.0f) * tanHalf * float(w) / float(h);
            const float ny = (1.0f - 2.0f * (float(y) + 0.5f) / float(h)) * tanHalf;
            const glm::vec3 dir = glm::normalize(f + nx * r + ny * u);
            float best = std::numeric_limits<float>::infinity();
            int bestReflector = -1;
            for (const DrawItem& d : s.draws)
                for (uint32_t i = 0; i + 2 < s.meshes[d.mesh].indexCount; i += 3) {
                    const float t = hitTriangle(pose.position, dir, worldVertex(s, d, i), worldVertex(s, d, i + 1), worldVertex(s, d, i + 2));
                    if (t < best) best = t, bestReflector = d.reflector;
                }
            onTile += bestReflector >= 0;
        }
    return float(onTile) / float(w * h);
}

}  // namespace

TEST(StressSpec, Parses) {
    EXPECT_EQ(parseStressSpec("stress:1"), 1u);
    EXPECT_EQ(parseStressSpec("stress:64"), 64u);
    EXPECT_EQ(parseStressSpec("stress:4096"), 4096u);
    EXPECT_EQ(parseStressSpec("foo.gltf"), std::nullopt);
    EXPECT_EQ(parseStressSpec(""), std::nullopt);
    EXPECT_EQ(parseStressSpec("stress"), std::nullopt);
}

TEST(StressSpec, RefusesBadCounts) {
    for (const char* bad : {"stress:0", "stress:4097", "stress:", "stress:12x", "stress:-3", "stress:+3", "stress: 5",
                            "stress:99999999999999999999"}) {
        const std::string msg = parseError(bad);
        EXPECT_EQ(msg, std::string("--scene ") + bad + ": expected stress:N with N a whole number in 1..4096") << bad;
    }
}

TEST(StressScene, RefusesOutOfRangeCounts) {
    EXPECT_THROW(makeStressScene(0), std::runtime_error);
    EXPECT_THROW(makeStressScene(kStressMaxTiles + 1), std::runtime_error);
}

class StressLayout : public ::testing::TestWithParam<uint32_t> {};

TEST_P(StressLayout, TilesMatchReflectors) {
    const uint32_t n = GetParam();
    const Scene s = makeStressScene(n);
    EXPECT_EQ(s.sourcePath, "stress:" + std::to_string(n));
    ASSERT_EQ(s.reflectors.size(), n);

    std::vector<int> drawOf(n, -1);
    for (size_t k = 0; k < s.draws.size(); ++k) {
        const DrawItem& d = s.draws[k];
        const Mesh& m = s.meshes[d.mesh];
        ASSERT_GE(m.material, 0);
        const bool reflective = s.materials[size_t(m.material)].reflective;
        if (d.reflector < 0) {
            EXPECT_FALSE(reflective) << d.nodeName;
            continue;
        }
        ASSERT_LT(d.reflector, int(n));
        EXPECT_TRUE(reflective);
        EXPECT_EQ(drawOf[size_t(d.reflector)], -1) << "two draws on reflector " << d.reflector;
        drawOf[size_t(d.reflector)] = int(k);
    }
    std::set<std::string> names;
    const float half = kStressFloorSize * 0.5f;
    float area = 0.0f;
    for (uint32_t i = 0; i < n; ++i) {
        const Reflector& r = s.reflectors[i];
        EXPECT_EQ(r.name, "tile_" + std::to_string(i));
        EXPECT_TRUE(names.insert(r.name).second);
        EXPECT_EQ(validateReflector(r), "") << r.name;
        EXPECT_EQ(r.kind, ReflectorKind::Opaque);
        EXPECT_FLOAT_EQ(r.reflectance, 0.85f);
        ASSERT_GE(drawOf[i], 0) << "no draw for " << r.name;
        const DrawItem& d = s.draws[size_t(drawOf[i])];
        // Every vertex on the plane and inside the rectangle, and the tile spans the rectangle.
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (uint32_t v = 0; v < s.meshes[d.mesh].indexCount; ++v) {
            const glm::vec3 p = worldVertex(s, d, v);
            EXPECT_NEAR(r.planeDistance(p), 0.0f, 1e-5f) << r.name;
            EXPECT_TRUE(r.containsProjected(p, 1e-4f)) << r.name;
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        EXPECT_NEAR(hi.x - lo.x, 2.0f * r.halfExtents.x, 1e-4f) << r.name;
        EXPECT_NEAR(hi.z - lo.z, 2.0f * r.halfExtents.y, 1e-4f) << r.name;
        EXPECT_GE(lo.x, -half - 1e-4f);
        EXPECT_LE(hi.x, half + 1e-4f);
        EXPECT_GE(lo.z, -half - 1e-4f);
        EXPECT_LE(hi.z, half + 1e-4f);
        area += tileArea(r);
    }
    // Same tiled area whatever N (within 10 %), so a sweep over N measures the reflector count.
    const float expected = kStressTileFill * kStressTileFill * kStressFloorSize * kStressFloorSize;
    EXPECT_NEAR(area, expected, 0.1f * expected);
}

TEST_P(StressLayout, TilesDoNotOverlap) {
    const Scene s = makeStressScene(GetParam());
    // All tiles are axis-aligned (tangent +X) on one plane, so 2D rectangle overlap suffices.
    for (size_t a = 0; a < s.reflectors.size(); ++a)
        for (size_t b = a + 1; b < s.reflectors.size(); ++b) {
            const Reflector &p = s.reflectors[a], &q = s.reflectors[b];
            const float ox = p.halfExtents.x + q.halfExtents.x - std::abs(p.center.x - q.center.x);
            const float oz = p.halfExtents.y + q.halfExtents.y - std::abs(p.center.z - q.center.z);
            ASSERT_FALSE(ox > 1e-5f && oz > 1e-5f) << p.name << " overlaps " << q.name;
        }
}

TEST_P(StressLayout, LoaderBindingRuleAgrees) {
    // The scaled, shared tile mesh must bind like loaded geometry: by name and, without names, by
    // the geometric rule on world-space vertices.
    const Scene s = makeStressScene(GetParam());
    for (bool keepNames : {true, false}) {
        Scene copy = s;
        for (DrawItem& d : copy.draws) {
            d.reflector = -1;
            if (!keepNames) d.nodeName.clear();
        }
        bindDrawsToReflectors(copy);
        for (size_t k = 0; k < s.draws.size(); ++k) EXPECT_EQ(copy.draws[k].reflector, s.draws[k].reflector) << keepNames << " " << k;
    }
}

TEST_P(StressLayout, MeshesAreWellFormed) {
    const Scene s = makeStressScene(GetParam());
    for (const Mesh& m : s.meshes) {
        ASSERT_EQ(m.indexCount % 3, 0u) << m.name;
        ASSERT_LE(size_t(m.firstIndex) + m.indexCount, s.indices.size());
        for (uint32_t i = 0; i < m.indexCount; i += 3) {
            const Vertex* v[3];
            for (int k = 0; k < 3; ++k) {
                const size_t idx = size_t(m.vertexOffset) + s.indices[m.firstIndex + i + uint32_t(k)];
                ASSERT_LT(idx, s.vertices.size());
                v[k] = &s.vertices[idx];
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(v[k]->position, m.boundsMin - 1e-5f))) << m.name;
                EXPECT_TRUE(glm::all(glm::lessThanEqual(v[k]->position, m.boundsMax + 1e-5f))) << m.name;
                EXPECT_NEAR(glm::length(v[k]->normal), 1.0f, 1e-4f) << m.name;
                EXPECT_NEAR(glm::length(glm::vec3(v[k]->tangent)), 1.0f, 1e-4f) << m.name;
                EXPECT_NEAR(glm::dot(v[k]->normal, glm::vec3(v[k]->tangent)), 0.0f, 1e-4f) << m.name;
                EXPECT_EQ(std::abs(v[k]->tangent.w), 1.0f) << m.name;
            }
            // Counter-clockwise seen from the side the normals point to (glTF front faces).
            const glm::vec3 face = glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
            EXPECT_GT(glm::dot(face, v[0]->normal + v[1]->normal + v[2]->normal), 0.0f) << m.name << " triangle " << i / 3;
        }
    }
    for (const DrawItem& d : s.draws)
        for (uint32_t i = 0; i < s.meshes[d.mesh].indexCount; ++i) {
            const glm::vec3 p = worldVertex(s, d, i);
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, s.boundsMin - 1e-4f)) && glm::all(glm::lessThanEqual(p, s.boundsMax + 1e-4f)))
                << d.nodeName;
        }
}

INSTANTIATE_TEST_SUITE_P(Counts, StressLayout, ::testing::Values(1u, 7u, 256u, 1024u));

TEST(StressScene, Deterministic) {
    const Scene a = makeStressScene(7), b = makeStressScene(7);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)), 0);
    EXPECT_EQ(a.indices, b.indices);
}

TEST(StressScene, SweepCamerasFrameTheirFractions) {
    const Scene s = makeStressScene(64);
    for (const char* name : {"overview", "reflective_5", "reflective_25", "reflective_100"}) ASSERT_NE(s.findCamera(name), nullptr) << name;
    // Coarse ray grid (64x36); bands are loose so the test guards the intent, not exact numbers.
    const float f5 = reflectiveFraction(s, s.findCamera("reflective_5")->pose, 64, 36);
    const float f25 = reflectiveFraction(s, s.findCamera("reflective_25")->pose, 64, 36);
    const float f100 = reflectiveFraction(s, s.findCamera("reflective_100")->pose, 64, 36);
    EXPECT_GT(f5, 0.02f);
    EXPECT_LT(f5, 0.09f);
    EXPECT_GT(f25, 0.18f);
    EXPECT_LT(f25, 0.33f);
    EXPECT_GT(f100, 0.80f);  // the rest is grout
    std::printf("reflective fractions: 5 -> %.3f, 25 -> %.3f, 100 -> %.3f\n", f5, f25, f100);
}
