// Reflector fitting (engine/scene/reflector_fit.hpp): minimum-area rectangles of planar triangle
// sets, refusal of curved / degenerate input, the planar region under a point, and the automatic fit
// of the default scene against its hand-authored reflectors.
#include "scene/reflector_fit.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace ppr::scene;

namespace {

constexpr float kPi = 3.14159265358979f;

// An orthonormal frame: tangent t, bitangent b = cross(n, t), normal n.
struct Frame {
    glm::vec3 t, b, n;
};

Frame randomFrame(std::mt19937& rng) {
    std::normal_distribution<float> g(0.0f, 1.0f);
    glm::vec3 n;
    do n = glm::vec3(g(rng), g(rng), g(rng));
    while (glm::length(n) < 1e-3f);
    n = glm::normalize(n);
    glm::vec3 t;
    do {
        t = glm::vec3(g(rng), g(rng), g(rng));
        t -= n * glm::dot(n, t);
    } while (glm::length(t) < 1e-3f);
    t = glm::normalize(t);
    return {t, glm::cross(n, t), n};
}

// Point in the frame's plane through c: c + t·u + b·v.
glm::vec3 at(const Frame& f, const glm::vec3& c, float u, float v) { return c + f.t * u + f.b * v; }

// A rectangle as a grid of nu × nv quads (two triangles each), wound along the frame's normal.
std::vector<glm::vec3> rectangle(const Frame& f, const glm::vec3& c, glm::vec2 half, int nu = 1, int nv = 1) {
    std::vector<glm::vec3> out;
    auto p = [&](int i, int j) {
        return at(f, c, -half.x + 2.0f * half.x * float(i) / float(nu), -half.y + 2.0f * half.y * float(j) / float(nv));
    };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) out.insert(out.end(), {p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j), p(i + 1, j + 1), p(i, j + 1)});
    return out;
}

// Sine of the angle between two lines (directions up to sign).
float lineAngle(const glm::vec3& a, const glm::vec3& b) { return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))); }

// Area of the tightest rectangle over all in-plane directions given by vertex pairs (a superset of
// the hull edge directions, so this is the exact minimum), brute force O(n^3).
double bruteMinArea(const std::vector<glm::dvec2>& pts) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < pts.size(); ++i)
        for (size_t j = i + 1; j < pts.size(); ++j) {
            const glm::dvec2 d = pts[j] - pts[i];
            if (glm::length(d) < 1e-9) continue;
            const glm::dvec2 e = glm::normalize(d), n(-e.y, e.x);
            double lo = 1e30, hi = -1e30, lo2 = 1e30, hi2 = -1e30;
            for (const auto& p : pts) {
                lo = std::min(lo, glm::dot(p, e));
                hi = std::max(hi, glm::dot(p, e));
                lo2 = std::min(lo2, glm::dot(p, n));
                hi2 = std::max(hi2, glm::dot(p, n));
            }
            best = std::min(best, (hi - lo) * (hi2 - lo2));
        }
    return best;
}

// Valid once named (fits come back unnamed; validateReflector requires a name).
void expectValid(Reflector r) {
    if (r.name.empty()) r.name = "fitted";
    EXPECT_EQ(validateReflector(r), "") << "fitted reflector invalid";
}

// Every vertex lies inside the fitted rectangle (grown by margin) and on its plane.
void expectContains(const Reflector& r, const std::vector<glm::vec3>& tris, float margin) {
    for (const glm::vec3& p : tris) {
        EXPECT_TRUE(r.containsProjected(p, margin)) << "vertex (" << p.x << ", " << p.y << ", " << p.z << ") outside";
        EXPECT_LE(std::abs(r.planeDistance(p)), 1e-3f);
    }
}

}  // namespace

TEST(FitReflector, RandomRectanglesAreRecovered) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<float> pos(-20.0f, 20.0f), ext(0.05f, 5.0f), ratio(1.2f, 4.0f);
    for (int iter = 0; iter < 300; ++iter) {
        const Frame f = randomFrame(rng);
        const glm::vec3 c(pos(rng), pos(rng), pos(rng));
        // Longer side along t or along b, so both tangent outcomes are exercised.
        const float shortSide = ext(rng), longSide = std::min(shortSide * ratio(rng), 8.0f);
        const bool longAlongT = iter % 2 == 0;
        const glm::vec2 half = longAlongT ? glm::vec2(longSide, shortSide) : glm::vec2(shortSide, longSide);
        const std::vector<glm::vec3> tris = rectangle(f, c, half, 1 + iter % 3, 1 + iter % 2);
        const auto r = fitReflector(tris);
        ASSERT_TRUE(r.has_value()) << "iteration " << iter;
        SCOPED_TRACE("iteration " + std::to_string(iter));
        expectValid(*r);
        EXPECT_LE(glm::length(r->center - c), 1e-4f);
        EXPECT_GE(glm::dot(r->normal, f.n), 1.0f - 1e-6f);  // oriented along the winding
        EXPECT_NEAR(r->halfExtents.x, longSide, 1e-4f);
        EXPECT_NEAR(r->halfExtents.y, shortSide, 1e-4f);
        EXPECT_LE(lineAngle(r->tangent, longAlongT ? f.t : f.b), 1e-4f);
        EXPECT_EQ(r->kind, ReflectorKind::Opaque);
        EXPECT_EQ(r->reflectance, 1.0f);
        EXPECT_EQ(r->name, "");
    }
}

TEST(FitReflector, ReversedWindingFlipsTheNormal) {
    const Frame f{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
    std::vector<glm::vec3> tris = rectangle(f, {1, 2, 3}, {2, 1});
    for (size_t i = 0; i < tris.size(); i += 3) std::swap(tris[i + 1], tris[i + 2]);
    const auto r = fitReflector(tris);
    ASSERT_TRUE(r);
    EXPECT_GE(glm::dot(r->normal, glm::vec3(0, -1, 0)), 0.999999f);
    EXPECT_GE(glm::dot(glm::cross(r->normal, r->tangent), r->bitangent()), 0.999f);
    expectValid(*r);
}

TEST(FitReflector, TwoSidedInputFindsItsPlane) {
    const Frame f{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}};
    std::vector<glm::vec3> tris = rectangle(f, {10.5f, 1.45f, -1.0f}, {2.5f, 1.2f});
    std::vector<glm::vec3> back = tris;
    for (size_t i = 0; i < back.size(); i += 3) std::swap(back[i + 1], back[i + 2]);
    tris.insert(tris.end(), back.begin(), back.end());
    const auto r = fitReflector(tris);
    ASSERT_TRUE(r);
    EXPECT_GE(std::abs(glm::dot(r->normal, f.n)), 0.999999f);
    EXPECT_LE(glm::length(r->center - glm::vec3(10.5f, 1.45f, -1.0f)), 1e-5f);
    EXPECT_NEAR(r->halfExtents.x, 2.5f, 1e-5f);
    EXPECT_NEAR(r->halfExtents.y, 1.2f, 1e-5f);
}

TEST(FitReflector, RotatedRectangleWithInteriorPoints) {
    // A 3 × 1 m rectangle turned 30° in a tilted plane, triangulated as fans from interior points
    // (its hull is just the four corners) plus small triangles strictly inside.
    std::mt19937 rng(7);
    const Frame base = randomFrame(rng);
    const float a = 30.0f * kPi / 180.0f;
    const Frame f{std::cos(a) * base.t + std::sin(a) * base.b, -std::sin(a) * base.t + std::cos(a) * base.b, base.n};
    const glm::vec3 c(-3.0f, 4.0f, 7.5f);
    const glm::vec2 half(1.5f, 0.5f);
    const glm::vec3 corners[4] = {at(f, c, -half.x, -half.y), at(f, c, half.x, -half.y), at(f, c, half.x, half.y),
                                  at(f, c, -half.x, half.y)};
    std::uniform_real_distribution<float> u(-0.9f, 0.9f);
    std::vector<glm::vec3> tris;
    const glm::vec3 hub = at(f, c, 0.4f, -0.2f);
    for (int i = 0; i < 4; ++i) tris.insert(tris.end(), {hub, corners[i], corners[(i + 1) % 4]});
    for (int i = 0; i < 20; ++i) {
        const float u0 = u(rng) * half.x, v0 = u(rng) * half.y;
        tris.insert(tris.end(), {at(f, c, u0, v0), at(f, c, u0 + 0.05f, v0), at(f, c, u0, v0 + 0.05f)});
    }
    const auto r = fitReflector(tris);
    ASSERT_TRUE(r);
    expectValid(*r);
    EXPECT_LE(glm::length(r->center - c), 1e-5f);
    EXPECT_GE(glm::dot(r->normal, f.n), 0.999999f);
    EXPECT_NEAR(r->halfExtents.x, 1.5f, 1e-5f);
    EXPECT_NEAR(r->halfExtents.y, 0.5f, 1e-5f);
    EXPECT_LE(lineAngle(r->tangent, f.t), 1e-5f);
    expectContains(*r, tris, 1e-5f);
}

TEST(FitReflector, IrregularPolygonGetsTheTightestRectangle) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> radius(0.4f, 2.0f), pos(-10.0f, 10.0f);
    for (int iter = 0; iter < 40; ++iter) {
        SCOPED_TRACE("iteration " + std::to_string(iter));
        const Frame f = randomFrame(rng);
        const glm::vec3 c(pos(rng), pos(rng), pos(rng));
        const int n = iter < 30 ? 5 + iter : 100 + 40 * (iter - 30);  // up to 460 outline points
        std::vector<glm::vec2> outline;  // star-shaped: random radius per evenly spread angle
        for (int i = 0; i < n; ++i) {
            const float th = 2.0f * kPi * float(i) / float(n);
            const float r = radius(rng) * (1.0f + 0.8f * float(iter % 3 == 0) * std::cos(th));  // some elongated
            outline.emplace_back(r * std::cos(th) + 0.3f, r * std::sin(th) - 0.1f);
        }
        std::vector<glm::vec3> tris;
        for (int i = 0; i < n; ++i) {
            const glm::vec2 p = outline[size_t(i)], q = outline[size_t((i + 1) % n)];
            tris.insert(tris.end(), {at(f, c, 0.3f, -0.1f), at(f, c, p.x, p.y), at(f, c, q.x, q.y)});
        }
        const auto r = fitReflector(tris);
        ASSERT_TRUE(r);
        expectValid(*r);
        expectContains(*r, tris, 1e-4f);
        EXPECT_GE(glm::dot(r->normal, f.n), 0.999999f);
        const double area = 4.0 * double(r->halfExtents.x) * double(r->halfExtents.y);
        // Never larger than the rectangle aligned with the generating frame...
        glm::vec2 lo(1e9f), hi(-1e9f);
        std::vector<glm::dvec2> pts;
        for (const glm::vec2& p : outline) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            pts.emplace_back(p);
        }
        EXPECT_LE(area, double(hi.x - lo.x) * double(hi.y - lo.y) * (1.0 + 1e-5));
        // ... and exactly the minimum over all edge directions (brute force).
        EXPECT_NEAR(area, bruteMinArea(pts), 1e-4 * area);
    }
}

TEST(FitReflector, CurvedAndBentInputIsRefused) {
    // A UV sphere of radius 0.5.
    std::vector<glm::vec3> sphere;
    const int seg = 16, rings = 8;
    auto sp = [&](int i, int j) {
        const float th = 2.0f * kPi * float(i) / float(seg), ph = kPi * (float(j) / float(rings) - 0.5f);
        return glm::vec3(0.3f, 0.5f, 0.8f) + 0.5f * glm::vec3(std::cos(ph) * std::cos(th), std::sin(ph), -std::cos(ph) * std::sin(th));
    };
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < seg; ++i) sphere.insert(sphere.end(), {sp(i, j), sp(i + 1, j), sp(i + 1, j + 1), sp(i, j), sp(i + 1, j + 1), sp(i, j + 1)});
    EXPECT_FALSE(fitReflector(sphere));
    // A 1 × 1 m patch of a sphere of radius 20 m (nearly flat: sagitta over the diagonal ~ 12 mm).
    std::vector<glm::vec3> cap;
    auto onBig = [](float x, float z) { return glm::vec3(x, std::sqrt(400.0f - x * x - z * z) - 20.0f, z); };
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const float x0 = -0.5f + 0.25f * float(i), z0 = -0.5f + 0.25f * float(j), x1 = x0 + 0.25f, z1 = z0 + 0.25f;
            cap.insert(cap.end(), {onBig(x0, z0), onBig(x0, z1), onBig(x1, z1), onBig(x0, z0), onBig(x1, z1), onBig(x1, z0)});
        }
    EXPECT_FALSE(fitReflector(cap));
    EXPECT_TRUE(fitReflector(cap, 0.02f));
    // A 2 × 2 m quad folded along its diagonal by 1 cm.
    const glm::vec3 a(0, 0, 0), b(2, 0, 0), c(2, 0.01f, -2), d(0, 0, -2);
    const std::vector<glm::vec3> bent = {a, b, c, a, c, d};
    const std::vector<glm::vec3> bentOther = {a, b, d, b, c, d};  // the other diagonal: c out of plane
    EXPECT_FALSE(fitReflector(bent));
    EXPECT_FALSE(fitReflector(bentOther));
    EXPECT_TRUE(fitReflector(bent, 0.01f));  // accepted at a looser tolerance
    // A 0.2 mm fold passes the default 1 mm tolerance.
    const std::vector<glm::vec3> nearlyFlat = {a, b, c - glm::vec3(0, 0.0098f, 0), a, c - glm::vec3(0, 0.0098f, 0), d};
    EXPECT_TRUE(fitReflector(nearlyFlat));
}

TEST(FitReflector, DegenerateInputIsRefused) {
    EXPECT_FALSE(fitReflector({}));
    EXPECT_FALSE(fitReflector({{0, 0, 0}, {1, 0, 0}}));                          // not a multiple of 3
    EXPECT_FALSE(fitReflector({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}}));  // trailing vertex
    EXPECT_FALSE(fitReflector({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}}));              // a point
    // Collinear points, several triangles along one line.
    std::vector<glm::vec3> line;
    for (int i = 0; i < 10; ++i) line.insert(line.end(), {glm::vec3(0.1f * i, 0.2f * i, -0.3f * i), glm::vec3(0.1f * i + 0.1f, 0.2f * i + 0.2f, -0.3f * i - 0.3f), glm::vec3(0.1f * i + 0.05f, 0.2f * i + 0.1f, -0.3f * i - 0.15f)});
    EXPECT_FALSE(fitReflector(line));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(fitReflector({{0, 0, 0}, {1, 0, 0}, {nan, 0, 1}}));
    EXPECT_FALSE(fitReflector({{0, 0, 0}, {1, 0, 0}, {0, 0, std::numeric_limits<float>::infinity()}}));
    // A 5 m sliver 0.05 mm wide: below kMinHalfExtent across.
    EXPECT_FALSE(fitReflector({{0, 0, 0}, {5, 0, 0}, {5, 0, -5e-5f}}));
    // A single triangle is fine.
    const auto tri = fitReflector({{0, 0, 0}, {1, 0, 0}, {0, 0, -1}});
    ASSERT_TRUE(tri);
    EXPECT_NEAR(4.0f * tri->halfExtents.x * tri->halfExtents.y, 1.0f, 1e-5f);  // min rectangle of a right triangle: its legs
    EXPECT_GE(glm::dot(tri->normal, glm::vec3(0, 1, 0)), 0.999999f);
}

TEST(FitReflector, SquareTieBreakIsDeterministic) {
    // A square turned 45° about +Y: both sides are equally long; the tangent must not depend on the
    // triangle order or starting vertex.
    const float s = std::sqrt(0.5f);
    const Frame f{{s, 0, s}, {0, 0, 0}, {0, 1, 0}};
    const Frame g{f.t, glm::cross(f.n, f.t), f.n};
    const std::vector<glm::vec3> tris = rectangle(g, {1, 0, 2}, {1, 1}, 2, 2);
    const auto first = fitReflector(tris);
    ASSERT_TRUE(first);
    std::mt19937 rng(5);
    for (int i = 0; i < 20; ++i) {
        std::vector<glm::vec3> shuffled = tris;
        // Shuffle whole triangles and rotate each triangle's vertices (winding preserved).
        std::vector<size_t> order(tris.size() / 3);
        for (size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::shuffle(order.begin(), order.end(), rng);
        for (size_t k = 0; k < order.size(); ++k)
            for (size_t v = 0; v < 3; ++v) shuffled[3 * k + v] = tris[3 * order[k] + (v + k) % 3];
        const auto r = fitReflector(shuffled);
        ASSERT_TRUE(r);
        EXPECT_LE(glm::length(r->tangent - first->tangent), 1e-5f);
        EXPECT_LE(glm::length(r->center - first->center), 1e-5f);
    }
    // The canonical choice: of (s, 0, s) and (s, 0, -s) (signs canonical), the lexicographically larger.
    EXPECT_LE(glm::length(first->tangent - glm::vec3(s, 0, s)), 1e-5f);
    // Signs: the largest component of the tangent is positive.
    const auto xz = fitReflector(rectangle(Frame{{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {0, 0, 0}, {3, 1}));
    ASSERT_TRUE(xz);
    EXPECT_LE(glm::length(xz->tangent - glm::vec3(1, 0, 0)), 1e-6f);
}

namespace {

Vertex vert(glm::vec3 p) { return Vertex{p, {0, 1, 0}, glm::vec4(1, 0, 0, 1), {0, 0}}; }

// A scene holding one unit quad mesh (object space x, z in [-1, 1], y = 0, facing +Y) and a
// sphere-ish curved mesh; materials: 0 plain, 1 reflective, 2 reflective glass.
Scene smallScene() {
    Scene s;
    s.vertices = {vert({-1, 0, -1}), vert({1, 0, -1}), vert({1, 0, 1}), vert({-1, 0, 1})};
    s.indices = {0, 3, 2, 0, 2, 1};
    s.meshes.push_back(Mesh{"quad", 0, 6, 0, 1, {-1, 0, -1}, {1, 0, 1}});
    // A "tent" (two quads meeting at a ridge): not planar.
    const int32_t base = int32_t(s.vertices.size());
    for (glm::vec3 p : {glm::vec3(-1, 0, -1), glm::vec3(0, 0.5f, -1), glm::vec3(1, 0, -1), glm::vec3(-1, 0, 1), glm::vec3(0, 0.5f, 1),
                        glm::vec3(1, 0, 1)})
        s.vertices.push_back(vert(p));
    const uint32_t first = uint32_t(s.indices.size());
    for (uint32_t i : {0u, 3u, 4u, 0u, 4u, 1u, 1u, 4u, 5u, 1u, 5u, 2u}) s.indices.push_back(i);
    s.meshes.push_back(Mesh{"tent", first, 12, base, 1, {-1, 0, -1}, {1, 0.5f, 1}});
    s.materials.push_back(Material{.name = "plain"});
    s.materials.push_back(Material{.name = "mirror", .reflective = true});
    s.materials.push_back(Material{.name = "glass", .reflective = true, .transparent = true});
    return s;
}

DrawItem drawOf(uint32_t mesh, glm::mat4 world, std::string name) {
    DrawItem d;
    d.mesh = mesh;
    d.world = world;
    d.nodeName = std::move(name);
    return d;
}

}  // namespace

TEST(WorldTriangles, TransformsAndGuards) {
    Scene s = smallScene();
    const glm::mat4 w = glm::scale(glm::translate(glm::mat4(1), {2, 3, 4}), glm::vec3(0.5f));
    const std::vector<glm::vec3> t = worldTriangles(s, drawOf(0, w, "q"));
    ASSERT_EQ(t.size(), 6u);
    EXPECT_EQ(t[0], glm::vec3(1.5f, 3.0f, 3.5f));
    EXPECT_EQ(t[1], glm::vec3(1.5f, 3.0f, 4.5f));
    EXPECT_EQ(t[2], glm::vec3(2.5f, 3.0f, 4.5f));
    EXPECT_EQ(worldTriangles(s, drawOf(1, glm::mat4(1), "tent")).size(), 12u);
    EXPECT_TRUE(worldTriangles(s, drawOf(7, glm::mat4(1), "bad mesh")).empty());
    s.meshes[0].indexCount = 600;  // past the index buffer
    EXPECT_TRUE(worldTriangles(s, drawOf(0, glm::mat4(1), "q")).empty());
    s.meshes[0].indexCount = 6;
    s.indices[0] = 100;  // vertex out of range
    EXPECT_TRUE(worldTriangles(s, drawOf(0, glm::mat4(1), "q")).empty());
}

TEST(AutoFitAll, ReflectivePlanarDrawsInOrder) {
    Scene s = smallScene();
    s.meshes.push_back(Mesh{"glass_quad", 0, 6, 0, 2, {-1, 0, -1}, {1, 0, 1}});
    s.meshes.push_back(Mesh{"plain_quad", 0, 6, 0, 0, {-1, 0, -1}, {1, 0, 1}});
    const glm::mat4 upright = glm::rotate(glm::translate(glm::mat4(1), {0, 1, -5}), kPi / 2, glm::vec3(1, 0, 0));
    s.draws = {drawOf(1, glm::mat4(1), "tent"),                                                   // curved: skipped
               drawOf(0, glm::scale(glm::translate(glm::mat4(1), {3, 0.01f, 0}), {2, 1, 1}), "wide"),  // 4 × 2 m
               drawOf(3, glm::mat4(1), "plain"),                                                  // not reflective
               drawOf(2, upright, "pane"),                                                        // glass, facing +Z
               drawOf(9, glm::mat4(1), "broken")};
    const std::vector<Reflector> rs = autoFitAll(s);
    ASSERT_EQ(rs.size(), 2u);
    EXPECT_EQ(rs[0].name, "wide");
    EXPECT_EQ(rs[0].kind, ReflectorKind::Opaque);
    EXPECT_LE(glm::length(rs[0].center - glm::vec3(3, 0.01f, 0)), 1e-6f);
    EXPECT_NEAR(rs[0].halfExtents.x, 2.0f, 1e-6f);
    EXPECT_NEAR(rs[0].halfExtents.y, 1.0f, 1e-6f);
    EXPECT_LE(glm::length(rs[0].tangent - glm::vec3(1, 0, 0)), 1e-6f);
    EXPECT_GE(rs[0].normal.y, 0.999999f);
    EXPECT_EQ(rs[1].name, "pane");
    EXPECT_EQ(rs[1].kind, ReflectorKind::Glass);
    EXPECT_GE(rs[1].normal.z, 0.999999f);
    EXPECT_LE(glm::length(rs[1].center - glm::vec3(0, 1, -5)), 1e-6f);
    for (const Reflector& r : rs) expectValid(r);

    // Unnamed nodes: the mesh name, else the draw index.
    s.draws = {drawOf(0, glm::mat4(1), ""), drawOf(3, glm::mat4(1), "")};
    s.meshes[3].material = 1;
    s.meshes[3].name.clear();
    const std::vector<Reflector> unnamed = autoFitAll(s);
    ASSERT_EQ(unnamed.size(), 2u);
    EXPECT_EQ(unnamed[0].name, "quad");
    EXPECT_EQ(unnamed[1].name, "draw_1");
}

TEST(FitPlanarRegion, ConnectedCoplanarTrianglesUnderThePoint) {
    Scene s = smallScene();
    auto at3 = [](glm::vec3 t) { return glm::translate(glm::mat4(1), t); };
    s.draws = {
        drawOf(0, at3({0, 0, 0}), "a"),           // [-1, 1]²
        drawOf(0, at3({2, 0, 0}), "a_east"),      // shares an edge with a: one 4 × 2 region
        drawOf(0, at3({10, 0, 0}), "far"),        // same plane, not connected
        drawOf(0, at3({0, 0.05f, 0}), "raised"),  // parallel plane 5 cm up
        drawOf(0, glm::rotate(at3({0, 0.0005f, 4}), kPi, glm::vec3(1, 0, 0)), "down"),  // coplanar, facing down
        drawOf(1, at3({0, 0, 0}), "tent"),        // touches the plane at its eaves only
    };
    // The point is on "a": the region is a ∪ a_east.
    auto r = fitPlanarRegion(s, {0.2f, 0.0003f, 0.1f}, {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_LE(glm::length(r->center - glm::vec3(1, 0, 0)), 1e-6f);
    EXPECT_NEAR(r->halfExtents.x, 2.0f, 1e-6f);
    EXPECT_NEAR(r->halfExtents.y, 1.0f, 1e-6f);
    EXPECT_GE(r->normal.y, 0.999999f);
    expectValid(*r);
    // Off every triangle: the nearest one in the plane ("far" at x in [9, 11]).
    r = fitPlanarRegion(s, {8.0f, 0.0f, 0.5f}, {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_LE(glm::length(r->center - glm::vec3(10, 0, 0)), 1e-6f);
    EXPECT_NEAR(r->halfExtents.x, 1.0f, 1e-6f);
    // The raised plane.
    r = fitPlanarRegion(s, {0, 0.05f, 0}, {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_NEAR(r->center.y, 0.05f, 1e-6f);
    EXPECT_NEAR(r->halfExtents.x, 1.0f, 1e-6f);
    // Facing down at z = 4: only the flipped quad qualifies.
    r = fitPlanarRegion(s, {0, 0, 4}, {0, -1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_LE(glm::length(r->center - glm::vec3(0, 0.0005f, 4)), 1e-6f);
    EXPECT_LE(r->normal.y, -0.999999f);
    // Nothing faces +X anywhere on x = 0.5.
    EXPECT_FALSE(fitPlanarRegion(s, {0.5f, 0, 0}, {1, 0, 0}, 1e-3f));
    EXPECT_FALSE(fitPlanarRegion(s, {0, 0, 0}, {0, 0, 0}, 1e-3f));
}

// --- The default scene ------------------------------------------------------------------------

namespace {

struct DefaultSceneData {
    Scene scene;
    std::vector<Reflector> authored;
};

const DefaultSceneData& defaultScene() {
    static const DefaultSceneData data = [] {
        DefaultSceneData d;
        const std::filesystem::path gltf = PPR_DEFAULT_SCENE_FILE;
        d.scene = loadGltf(gltf.string());
        d.authored = loadReflectorFile((gltf.parent_path() / "default.reflectors.json").string());
        return d;
    }();
    return data;
}

const Reflector* byName(const std::vector<Reflector>& rs, const std::string& name) {
    for (const Reflector& r : rs)
        if (r.name == name) return &r;
    return nullptr;
}

// Differences between a fitted reflector and the authored one, with the fit's axes mapped onto the
// authored axes (the fit's tangent may be the authored bitangent, and either may be negated).
struct Diff {
    float center = 0;     // metres
    float normalDot = 0;  // 1 = identical
    float axisAngle = 0;  // degrees between the fitted rectangle's axes and the authored ones
    glm::vec2 extents{0};  // fitted − authored half extents, along the authored tangent / bitangent
};

Diff compare(const Reflector& fit, const Reflector& ref) {
    Diff d;
    d.center = glm::length(fit.center - ref.center);
    d.normalDot = glm::dot(fit.normal, ref.normal);
    const float alongT = std::abs(glm::dot(fit.tangent, ref.tangent)), alongB = std::abs(glm::dot(fit.tangent, ref.bitangent()));
    const bool swapped = alongB > alongT;
    d.axisAngle = std::acos(std::min(1.0f, std::max(alongT, alongB))) * 180.0f / kPi;
    const glm::vec2 mapped = swapped ? glm::vec2(fit.halfExtents.y, fit.halfExtents.x) : fit.halfExtents;
    d.extents = mapped - ref.halfExtents;
    return d;
}

// Every authored reflector is reproduced to float precision: the mirror, stair treads and glass panes
// are exactly their meshes' rectangles, and the generator authors each puddle as the tightest
// rectangle around its wobbly outline (before that, the puddles carried design margins of 2–37 cm and
// the fit differed by up to 10 cm in centre and 30 cm in extent).
constexpr float kExactTolerance = 1e-4f;  // metres
bool isPuddle(const std::string& name) { return name.rfind("puddle_", 0) == 0; }

}  // namespace

TEST(DefaultSceneFit, AutoFitReproducesAuthored) {
    const DefaultSceneData& d = defaultScene();
    ASSERT_FALSE(d.authored.empty());
    ASSERT_EQ(d.authored.size(), d.scene.reflectors.size());
    const std::vector<Reflector> fits = autoFitAll(d.scene);

    // The curved reflective surfaces are not fitted; every authored reflector is.
    EXPECT_FALSE(byName(fits, "sphere_chrome"));
    EXPECT_FALSE(byName(fits, "post_steel"));
    EXPECT_EQ(fits.size(), d.authored.size());
    // Reflective draws exist for the curved ones (the fit refused them, they were not skipped by material).
    int curvedReflective = 0;
    for (const DrawItem& draw : d.scene.draws)
        if ((draw.nodeName == "sphere_chrome" || draw.nodeName == "post_steel") &&
            d.scene.materials[size_t(d.scene.meshes[draw.mesh].material)].reflective)
            ++curvedReflective;
    EXPECT_EQ(curvedReflective, 2);

    std::printf("%-14s %10s %12s %9s %18s %18s %9s\n", "reflector", "centre(m)", "1-normalDot", "axis(deg)", "fit half(t,b)",
                "authored half", "area %");
    for (const Reflector& ref : d.authored) {
        SCOPED_TRACE(ref.name);
        const Reflector* fit = byName(fits, ref.name);
        ASSERT_TRUE(fit) << ref.name << " was not fitted";
        expectValid(*fit);
        EXPECT_EQ(fit->kind, ref.kind);
        const Diff diff = compare(*fit, ref);
        const glm::vec2 mapped = ref.halfExtents + diff.extents;
        const float areaRatio = mapped.x * mapped.y / (ref.halfExtents.x * ref.halfExtents.y);
        std::printf("%-14s %10.5f %12.2e %9.3f %8.4f,%8.4f  %8.4f,%8.4f %9.2f\n", ref.name.c_str(), diff.center,
                    1.0f - diff.normalDot, diff.axisAngle, mapped.x, mapped.y, ref.halfExtents.x, ref.halfExtents.y,
                    100.0f * areaRatio);
        EXPECT_GE(diff.normalDot, 0.9999f);
        // The tight rectangle is never larger than the authored one (which encloses the mesh).
        EXPECT_LE(areaRatio, 1.0f + 1e-4f);
        // And it encloses every vertex of the draw. The authored design margin: the gap between the
        // mesh's extent along the authored axes and the authored rectangle (smallest over the 4 sides).
        float gap[4] = {1e9f, 1e9f, 1e9f, 1e9f};  // +t, -t, +b, -b sides
        for (const DrawItem& draw : d.scene.draws) {
            if (draw.nodeName != ref.name) continue;
            const std::vector<glm::vec3> tris = worldTriangles(d.scene, draw);
            expectContains(*fit, tris, 1e-4f);
            for (const glm::vec3& p : tris) {
                const float u = glm::dot(p - ref.center, ref.tangent), v = glm::dot(p - ref.center, ref.bitangent());
                gap[0] = std::min(gap[0], ref.halfExtents.x - u);
                gap[1] = std::min(gap[1], ref.halfExtents.x + u);
                gap[2] = std::min(gap[2], ref.halfExtents.y - v);
                gap[3] = std::min(gap[3], ref.halfExtents.y + v);
            }
        }
        const float margin = std::min({gap[0], gap[1], gap[2], gap[3]});
        // How far the fitted rectangle's corners stick out of the authored one (rotated fits can).
        float overshoot = 0.0f;
        for (float su : {-1.0f, 1.0f})
            for (float sv : {-1.0f, 1.0f}) {
                const glm::vec3 q = fit->center + su * fit->halfExtents.x * fit->tangent + sv * fit->halfExtents.y * fit->bitangent() - ref.center;
                overshoot = std::max({overshoot, std::abs(glm::dot(q, ref.tangent)) - ref.halfExtents.x,
                                      std::abs(glm::dot(q, ref.bitangent())) - ref.halfExtents.y});
            }
        std::printf("%-14s   mesh-to-authored gaps (+t -t +b -b) %.4f %.4f %.4f %.4f m; fitted corners outside authored %.4f m\n",
                    "", gap[0], gap[1], gap[2], gap[3], overshoot);
        EXPECT_NEAR(margin, 0.0f, kExactTolerance) << (isPuddle(ref.name) ? "puddle" : "quad");
        EXPECT_LE(overshoot, kExactTolerance);
        EXPECT_LE(diff.center, kExactTolerance);
        EXPECT_LE(diff.axisAngle, 0.1f);  // acos of a float dot near 1: measured up to 0.05°
        EXPECT_NEAR(diff.extents.x, 0.0f, kExactTolerance);
        EXPECT_NEAR(diff.extents.y, 0.0f, kExactTolerance);
    }
}

TEST(DefaultSceneFit, PlanarRegionUnderAPoint) {
    const DefaultSceneData& d = defaultScene();
    const std::vector<Reflector> fits = autoFitAll(d.scene);

    // A point on puddle_large's surface, off its centre: that puddle's rectangle.
    const Reflector* authored = byName(d.authored, "puddle_large");
    const Reflector* fitted = byName(fits, "puddle_large");
    ASSERT_TRUE(authored && fitted);
    const glm::vec3 onPuddle = authored->center + 0.4f * authored->tangent - 0.3f * authored->bitangent();
    auto r = fitPlanarRegion(d.scene, onPuddle, {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_LE(glm::length(r->center - fitted->center), 1e-4f);
    EXPECT_NEAR(r->halfExtents.x, fitted->halfExtents.x, 1e-4f);
    EXPECT_NEAR(r->halfExtents.y, fitted->halfExtents.y, 1e-4f);
    const Diff diff = compare(*r, *authored);
    EXPECT_LE(diff.center, kExactTolerance);
    EXPECT_GE(diff.normalDot, 0.9999f);

    // A stair tread.
    const Reflector* step = byName(d.authored, "step_3");
    ASSERT_TRUE(step);
    r = fitPlanarRegion(d.scene, step->center + glm::vec3(1.0f, 0.0f, 0.1f), {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    const Diff stepDiff = compare(*r, *step);
    EXPECT_LE(stepDiff.center, kExactTolerance);
    EXPECT_NEAR(stepDiff.extents.x, 0.0f, kExactTolerance);
    EXPECT_NEAR(stepDiff.extents.y, 0.0f, kExactTolerance);

    // A point on the bare floor, away from the puddles: the whole 24 × 24 m floor.
    r = fitPlanarRegion(d.scene, {8.0f, 0.0f, 6.0f}, {0, 1, 0}, 1e-3f);
    ASSERT_TRUE(r);
    EXPECT_LE(glm::length(r->center - glm::vec3(0, 0, 0)), 1e-3f);
    EXPECT_NEAR(r->halfExtents.x, 12.0f, 1e-3f);
    EXPECT_NEAR(r->halfExtents.y, 12.0f, 1e-3f);
    EXPECT_GE(r->normal.y, 0.9999f);
    std::printf("floor region: centre (%.4f, %.4f, %.4f) half (%.4f, %.4f)\n", r->center.x, r->center.y, r->center.z,
                r->halfExtents.x, r->halfExtents.y);
}
