#include "scene/tangents.hpp"

#include <cmath>

namespace ppr::scene::detail {

glm::vec3 anyOrthogonal(const glm::vec3& n) {
    // Cross with the axis least aligned with n, which can never be parallel to it.
    const glm::vec3 a = std::abs(n.x) < 0.577f ? glm::vec3(1, 0, 0)
                      : std::abs(n.y) < 0.577f ? glm::vec3(0, 1, 0)
                                               : glm::vec3(0, 0, 1);
    return glm::normalize(glm::cross(n, a));
}

void generateFlatNormals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    std::vector<Vertex> flat;
    flat.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        Vertex v[3] = {vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]]};
        glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        // Scaled to its largest component first: a tiny triangle's squared length is subnormal (or 0),
        // and dividing by its imprecise root gives a normal percent off unit length (found by fuzz_gltf).
        // An overflowing one (inf − inf is NaN, which max() may skip) is degenerate too.
        const float largest = glm::max(glm::abs(n.x), glm::max(glm::abs(n.y), glm::abs(n.z)));
        const bool usable = largest > 0.0f && std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z);
        n = usable ? glm::normalize(n / largest) : glm::vec3(0, 1, 0);  // degenerate triangle
        for (auto& x : v) {
            x.normal = n;
            flat.push_back(x);
        }
    }
    vertices = std::move(flat);
    indices.resize(vertices.size());
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
}

void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices) {
    std::vector<glm::vec3> tan(vertices.size(), glm::vec3(0.0f)), bitan(vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        const glm::vec3 e1 = vertices[i1].position - vertices[i0].position;
        const glm::vec3 e2 = vertices[i2].position - vertices[i0].position;
        const glm::vec2 d1 = vertices[i1].uv0 - vertices[i0].uv0;
        const glm::vec2 d2 = vertices[i2].uv0 - vertices[i0].uv0;
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > 1e-12f)) continue;  // UVs collapse this triangle: contributes nothing
        const float r = 1.0f / det;
        const glm::vec3 s = (e1 * d2.y - e2 * d1.y) * r;  // dP/du
        const glm::vec3 b = (e2 * d1.x - e1 * d2.x) * r;  // dP/dv
        if (!std::isfinite(s.x + s.y + s.z + b.x + b.y + b.z)) continue;
        for (uint32_t i : {i0, i1, i2}) {
            tan[i] += s;
            bitan[i] += b;
        }
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 n = vertices[i].normal;
        glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);  // Gram-Schmidt
        const float len = glm::length(t);
        // Relative test: a tangent (nearly) along n leaves only rounding noise after Gram-Schmidt.
        t = (len > 1e-4f * glm::length(tan[i]) && len > 0.0f && std::isfinite(len)) ? t / len : anyOrthogonal(n);
        const float w = glm::dot(glm::cross(n, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
        vertices[i].tangent = glm::vec4(t, w);
    }
}

}  // namespace ppr::scene::detail
