#include "mesh_builder.hpp"

#include "noise.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace gen {

namespace {

constexpr float kPi = 3.14159265358979f;

// One vertex of a planar face: tangent = u direction, image "up" = cross(n, u), so w = +1.
uint32_t planarVertex(MeshData& m, const glm::vec3& p, const glm::vec3& n, const glm::vec3& u, float texMetres) {
    const glm::vec3 v = glm::cross(n, u);
    const glm::vec2 uv(glm::dot(p, u) / texMetres, -glm::dot(p, v) / texMetres);
    return m.addVertex(p, n, glm::vec4(u, 1.0f), uv);
}

// Parametric surface P(s, t), s around / along u, t "up" the texture. `eval` returns position,
// normal and the (unnormalised) derivatives dP/ds, dP/dt; arc lengths give the UVs.
struct SurfacePoint {
    glm::vec3 p, n, dpds, dpdt;
};

void addSurface(MeshData& m, int segS, int segT, float lengthS, float lengthT, float texMetres,
                const std::function<SurfacePoint(float, float)>& eval) {
    const uint32_t first = m.vertexCount();
    for (int j = 0; j <= segT; ++j) {
        const float t = static_cast<float>(j) / static_cast<float>(segT);
        for (int i = 0; i <= segS; ++i) {
            const float s = static_cast<float>(i) / static_cast<float>(segS);
            const SurfacePoint sp = eval(s, t);
            glm::vec3 tan = sp.dpds - sp.n * glm::dot(sp.n, sp.dpds);
            tan = glm::length(tan) > 1e-8f ? glm::normalize(tan) : glm::vec3(1, 0, 0);
            const float w = glm::dot(glm::cross(sp.n, tan), sp.dpdt) >= 0.0f ? 1.0f : -1.0f;
            m.addVertex(sp.p, sp.n, glm::vec4(tan, w), glm::vec2(s * lengthS / texMetres, -t * lengthT / texMetres));
        }
    }
    const uint32_t row = static_cast<uint32_t>(segS + 1);
    for (int j = 0; j < segT; ++j) {
        for (int i = 0; i < segS; ++i) {
            const uint32_t a = first + static_cast<uint32_t>(j) * row + static_cast<uint32_t>(i);
            m.addTriangle(a, a + 1, a + row + 1);
            m.addTriangle(a, a + row + 1, a + row);
        }
    }
}

}  // namespace

uint32_t MeshData::addVertex(const glm::vec3& p, const glm::vec3& n, const glm::vec4& t, const glm::vec2& uv) {
    positions.push_back(p);
    normals.push_back(glm::normalize(n));
    tangents.push_back(t);
    uvs.push_back(uv);
    return static_cast<uint32_t>(positions.size() - 1);
}

void MeshData::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    const glm::vec3 g = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
    if (glm::length(g) < 1e-10f) return;
    const glm::vec3 n = normals[a] + normals[b] + normals[c];
    if (glm::dot(g, n) < 0.0f) std::swap(b, c);
    indices.insert(indices.end(), {a, b, c});
}

void addQuad(MeshData& m, const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, float texMetres) {
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    const glm::vec3 un = glm::normalize(u);
    const uint32_t a = planarVertex(m, origin, n, un, texMetres);
    const uint32_t b = planarVertex(m, origin + u, n, un, texMetres);
    const uint32_t c = planarVertex(m, origin + u + v, n, un, texMetres);
    const uint32_t d = planarVertex(m, origin + v, n, un, texMetres);
    m.addTriangle(a, b, c);
    m.addTriangle(a, c, d);
}

void addBox(MeshData& m, const glm::vec3& lo, const glm::vec3& hi, float texMetres, unsigned faces) {
    const glm::vec3 e = hi - lo;
    // Each face as origin + u + v with cross(u, v) pointing outwards and v "up" where possible.
    if (faces & PosX) addQuad(m, {hi.x, lo.y, hi.z}, {0, 0, -e.z}, {0, e.y, 0}, texMetres);
    if (faces & NegX) addQuad(m, {lo.x, lo.y, lo.z}, {0, 0, e.z}, {0, e.y, 0}, texMetres);
    if (faces & PosY) addQuad(m, {lo.x, hi.y, hi.z}, {e.x, 0, 0}, {0, 0, -e.z}, texMetres);
    if (faces & NegY) addQuad(m, {lo.x, lo.y, lo.z}, {e.x, 0, 0}, {0, 0, e.z}, texMetres);
    if (faces & PosZ) addQuad(m, {lo.x, lo.y, hi.z}, {e.x, 0, 0}, {0, e.y, 0}, texMetres);
    if (faces & NegZ) addQuad(m, {hi.x, lo.y, lo.z}, {-e.x, 0, 0}, {0, e.y, 0}, texMetres);
}

void addCylinder(MeshData& m, const glm::vec3& base, float rBottom, float rTop, float height, int segments,
                 bool bottomCap, bool topCap, float texMetres) {
    const float slant = std::sqrt(height * height + (rBottom - rTop) * (rBottom - rTop));
    const float rMax = std::max(rBottom, rTop);
    // P = (r cos θ, y, −r sin θ): θ increasing makes cross(dP/dθ, +Y) point outwards.
    addSurface(m, segments, 1, 2.0f * kPi * rMax, slant, texMetres, [&](float s, float t) {
        const float th = 2.0f * kPi * s;
        const float r = rBottom + (rTop - rBottom) * t;
        const glm::vec3 radial(std::cos(th), 0.0f, -std::sin(th));
        SurfacePoint sp;
        sp.p = base + radial * r + glm::vec3(0, height * t, 0);
        sp.dpds = glm::vec3(-std::sin(th), 0.0f, -std::cos(th));
        sp.dpdt = radial * (rTop - rBottom) + glm::vec3(0, height, 0);
        sp.n = glm::normalize(glm::cross(sp.dpds, sp.dpdt));
        return sp;
    });
    if (bottomCap) addDisk(m, base, rBottom, segments, false, texMetres);
    if (topCap) addDisk(m, base + glm::vec3(0, height, 0), rTop, segments, true, texMetres);
}

void addSphere(MeshData& m, const glm::vec3& center, float radius, int segments, int rings, float texMetres) {
    addSurface(m, segments, rings, 2.0f * kPi * radius, kPi * radius, texMetres, [&](float s, float t) {
        const float th = 2.0f * kPi * s;
        const float ph = kPi * (t - 0.5f);
        const glm::vec3 dir(std::cos(ph) * std::cos(th), std::sin(ph), -std::cos(ph) * std::sin(th));
        SurfacePoint sp;
        sp.p = center + dir * radius;
        sp.n = dir;
        sp.dpds = glm::vec3(-std::sin(th), 0.0f, -std::cos(th));  // well defined at the poles too
        sp.dpdt = glm::vec3(-std::sin(ph) * std::cos(th), std::cos(ph), std::sin(ph) * std::sin(th));
        return sp;
    });
}

void addDisk(MeshData& m, const glm::vec3& center, float radius, int segments, bool facingUp, float texMetres) {
    const glm::vec3 n(0, facingUp ? 1.0f : -1.0f, 0);
    const glm::vec3 u(1, 0, 0);
    const uint32_t c = planarVertex(m, center, n, u, texMetres);
    const uint32_t first = m.vertexCount();
    for (int i = 0; i <= segments; ++i) {
        const float th = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
        planarVertex(m, center + radius * glm::vec3(std::cos(th), 0, -std::sin(th)), n, u, texMetres);
    }
    for (int i = 0; i < segments; ++i) m.addTriangle(c, first + i, first + i + 1);
}

void addPuddle(MeshData& m, const glm::vec3& center, const glm::vec3& tangent, float halfU, float halfV,
               int segments, uint32_t seed) {
    const glm::vec3 n(0, 1, 0);
    const glm::vec3 t = glm::normalize(tangent);
    const glm::vec3 b = glm::cross(n, t);
    // A super-ellipse (fills the rectangle better than an ellipse) whose radius wobbles with a few
    // low-frequency harmonics; scaled to 0.97 of the rectangle so it never leaves it.
    const float a1 = 0.06f + 0.05f * hash01(seed, 1, 0), p1 = 6.2831853f * hash01(seed, 2, 0);
    const float a2 = 0.04f + 0.04f * hash01(seed, 3, 0), p2 = 6.2831853f * hash01(seed, 4, 0);
    const float a3 = 0.02f + 0.02f * hash01(seed, 5, 0), p3 = 6.2831853f * hash01(seed, 6, 0);
    const float texMetres = 2.0f;
    const uint32_t c = planarVertex(m, center, n, t, texMetres);
    const uint32_t first = m.vertexCount();
    for (int i = 0; i <= segments; ++i) {
        const float th = 2.0f * kPi * static_cast<float>(i % segments) / static_cast<float>(segments);
        const float ct = std::cos(th), st = std::sin(th);
        // |x|^4 + |y|^4 = 1 super-ellipse direction.
        const float se = std::pow(std::pow(std::fabs(ct), 4.0f) + std::pow(std::fabs(st), 4.0f), -0.25f);
        const float wobble = 1.0f - a1 - a2 - a3 + a1 * std::sin(2 * th + p1) + a2 * std::sin(3 * th + p2) +
                             a3 * std::sin(5 * th + p3);
        const float r = 0.97f * se * wobble;
        const glm::vec3 p = center + t * (halfU * r * ct) + b * (halfV * r * st);
        planarVertex(m, p, n, t, texMetres);
    }
    for (int i = 0; i < segments; ++i) m.addTriangle(c, first + i, first + i + 1);
}

void transformMesh(MeshData& m, const glm::mat3& rotation, const glm::vec3& offset) {
    for (size_t i = 0; i < m.positions.size(); ++i) {
        m.positions[i] = rotation * m.positions[i] + offset;
        m.normals[i] = glm::normalize(rotation * m.normals[i]);
        m.tangents[i] = glm::vec4(glm::normalize(rotation * glm::vec3(m.tangents[i])), m.tangents[i].w);
    }
}

void appendMesh(MeshData& m, const MeshData& other) {
    const uint32_t base = m.vertexCount();
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    m.normals.insert(m.normals.end(), other.normals.begin(), other.normals.end());
    m.tangents.insert(m.tangents.end(), other.tangents.begin(), other.tangents.end());
    m.uvs.insert(m.uvs.end(), other.uvs.begin(), other.uvs.end());
    for (uint32_t i : other.indices) m.indices.push_back(base + i);
}

}  // namespace gen
