#pragma once
// Internal to ppr_scene: the vertex attributes glTF lets a file omit (flat normals, tangents).
#include "scene/scene.hpp"

#include <vector>

namespace ppr::scene::detail {

// glTF: missing normals mean flat shading, so triangles are un-indexed (3 fresh vertices each) and
// get their face normal; indices become 0..n-1.
void generateFlatNormals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices);
// Per-vertex tangents from UV derivatives accumulated over triangles (Lengyel 2001), orthogonalised
// against the normal, with the bitangent sign in w. Vertices with degenerate UVs get an arbitrary
// unit tangent orthogonal to the normal.
void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices);
// A unit vector orthogonal to unit `n`.
glm::vec3 anyOrthogonal(const glm::vec3& n);

}  // namespace ppr::scene::detail
