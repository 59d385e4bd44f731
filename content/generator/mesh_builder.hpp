#pragma once
// Triangle-mesh building blocks for the default-scene generator: boxes, (tapered) cylinders,
// spheres, planar quads and puddle blobs, each with normals, glTF tangents (w = handedness) and
// UVs. UVs are planar/arc-length projections in metres divided by the texture's repeat size, so
// neighbouring faces of one mesh line up and texel density is the same everywhere.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace gen {

struct MeshData {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;  // xyz + w; bitangent = cross(normal, tangent.xyz) * w = image "up"
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;

    uint32_t addVertex(const glm::vec3& p, const glm::vec3& n, const glm::vec4& t, const glm::vec2& uv);
    // Adds a triangle, reordering it so that it is counter-clockwise seen from the side the vertex
    // normals point to (glTF front faces); degenerate triangles (pole caps) are dropped.
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    uint32_t vertexCount() const { return static_cast<uint32_t>(positions.size()); }
};

// Planar rectangle origin + s·u + t·v (s, t in 0..1); faces cross(u, v).
void addQuad(MeshData& m, const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v, float texMetres);

// Axis-aligned box; `faces` selects faces (bit order +X, -X, +Y, -Y, +Z, -Z) so hidden or
// separately-built faces (a step's reflective top) can be left out.
enum BoxFace : unsigned { PosX = 1, NegX = 2, PosY = 4, NegY = 8, PosZ = 16, NegZ = 32, AllFaces = 63 };
void addBox(MeshData& m, const glm::vec3& lo, const glm::vec3& hi, float texMetres, unsigned faces = AllFaces);

// Vertical (optionally tapered) cylinder standing on `base`; caps optional.
void addCylinder(MeshData& m, const glm::vec3& base, float rBottom, float rTop, float height, int segments,
                 bool bottomCap, bool topCap, float texMetres);

void addSphere(MeshData& m, const glm::vec3& center, float radius, int segments, int rings, float texMetres);

// Horizontal disk (normal +Y or -Y) at `center`.
void addDisk(MeshData& m, const glm::vec3& center, float radius, int segments, bool facingUp, float texMetres);

// Irregular puddle outline in the horizontal plane through `center`, facing +Y, strictly inside the
// rectangle center ± halfU·tangent ± halfV·bitangent (bitangent = cross(+Y, tangent)).
void addPuddle(MeshData& m, const glm::vec3& center, const glm::vec3& tangent, float halfU, float halfV,
               int segments, uint32_t seed);

// Rotates (orthonormal `rotation`) then translates positions, normals and tangents; UVs are kept,
// so a mesh can be built where world-projected UVs are wanted and then moved into node space.
void transformMesh(MeshData& m, const glm::mat3& rotation, const glm::vec3& offset);
// Appends `other` (indices rebased).
void appendMesh(MeshData& m, const MeshData& other);

}  // namespace gen
