// Generated normals and tangents (tangents.hpp), on synthetic meshes.
#include "scene/tangents.hpp"

#include "test_util.hpp"

#include <cmath>

using namespace ppr::scene;

namespace {

Vertex vert(glm::vec3 p, glm::vec2 uv, glm::vec3 n = {0, 0, 1}) { return Vertex{p, n, glm::vec4(0), uv}; }

void expectFrame(const Vertex& v) {
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
    EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-4f);
    EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
}

}  // namespace

TEST(Tangents, FollowUvDirection) {
    // Quad in XY facing +Z, u along +X, v along +Y.
    std::vector<Vertex> vs = {vert({0, 0, 0}, {0, 0}), vert({1, 0, 0}, {1, 0}), vert({1, 1, 0}, {1, 1}), vert({0, 1, 0}, {0, 1})};
    std::vector<uint32_t> idx = {0, 1, 2, 0, 2, 3};
    detail::generateTangents(vs, idx);
    for (const auto& v : vs) {
        expectFrame(v);
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);
        EXPECT_EQ(v.tangent.w, 1.0f);  // cross(n, t) = +Y = dP/dv
    }
    // Mirrored V flips the handedness sign.
    for (auto& v : vs) v.uv0.y = 1.0f - v.uv0.y;
    detail::generateTangents(vs, idx);
    for (const auto& v : vs) EXPECT_EQ(v.tangent.w, -1.0f);
}

TEST(Tangents, DegenerateUvsFallBackToOrthonormal) {
    std::vector<Vertex> vs = {vert({0, 0, 0}, {0.5f, 0.5f}, glm::normalize(glm::vec3(1, 2, 3))),
                              vert({1, 0, 0}, {0.5f, 0.5f}, glm::normalize(glm::vec3(1, 2, 3))),
                              vert({0, 1, 0}, {0.5f, 0.5f}, glm::normalize(glm::vec3(1, 2, 3)))};
    detail::generateTangents(vs, {0, 1, 2});
    for (const auto& v : vs) expectFrame(v);
}

TEST(Tangents, OrthogonalOnCurvedMesh) {
    // A bumpy grid with smooth normals: Gram-Schmidt must make every tangent orthogonal.
    std::vector<Vertex> vs;
    std::vector<uint32_t> idx;
    const int n = 9;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = float(i) / (n - 1), y = float(j) / (n - 1);
            const float z = 0.3f * std::sin(6 * x) * std::cos(5 * y);
            const glm::vec3 normal = glm::normalize(glm::vec3(-1.8f * std::cos(6 * x) * std::cos(5 * y), 1.5f * std::sin(6 * x) * std::sin(5 * y), 1));
            vs.push_back(vert({x, y, z}, {x * 2, y * 3}, normal));
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t a = uint32_t(j * n + i);
            idx.insert(idx.end(), {a, a + 1, a + n + 1, a, a + n + 1, a + n});
        }
    detail::generateTangents(vs, idx);
    for (const auto& v : vs) expectFrame(v);
}

TEST(Tangents, FlatNormalsUnindex) {
    std::vector<Vertex> vs = {vert({0, 0, 0}, {0, 0}), vert({1, 0, 0}, {1, 0}), vert({0, 0, -1}, {0, 1}), vert({5, 5, 5}, {0, 0})};
    std::vector<uint32_t> idx = {0, 1, 2, 2, 1, 0};
    detail::generateFlatNormals(vs, idx);
    ASSERT_EQ(vs.size(), 6u);
    EXPECT_EQ(idx, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_NEAR(vs[0].normal.y, 1.0f, 1e-6f);  // CCW seen from +Y
    EXPECT_NEAR(vs[3].normal.y, -1.0f, 1e-6f);
}

// A triangle 1e-11 across has a cross product whose squared length is subnormal: its normal must still
// be unit length (fuzz_gltf found one a percent off; tests/data/fuzz/regressions/gltf).
TEST(Tangents, FlatNormalOfATinyTriangleIsUnit) {
    for (float size : {1e-11f, 3e-12f, 1e-19f, 1e-30f}) {
        std::vector<Vertex> vs = {vert({0, 0, 0}, {0, 0}), vert({size, 0, 0}, {1, 0}), vert({0, 0, -size}, {0, 1})};
        std::vector<uint32_t> idx = {0, 1, 2};
        detail::generateFlatNormals(vs, idx);
        SCOPED_TRACE(size);
        for (const Vertex& v : vs) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
        EXPECT_NEAR(vs[0].normal.y, 1.0f, 1e-6f);
    }
}

// Edges so long that the cross product overflows (inf − inf: NaN components) count as degenerate.
TEST(Tangents, FlatNormalOfAnOverflowingTriangleFallsBack) {
    std::vector<Vertex> vs = {vert({0, 0, 0}, {0, 0}), vert({1e30f, 1e30f, 0}, {1, 0}), vert({1e30f, 1e30f, 1}, {0, 1})};  // z: inf − inf
    std::vector<uint32_t> idx = {0, 1, 2};
    detail::generateFlatNormals(vs, idx);
    for (const Vertex& v : vs) {
        EXPECT_TRUE(std::isfinite(v.normal.x) && std::isfinite(v.normal.y) && std::isfinite(v.normal.z));
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    }
}
