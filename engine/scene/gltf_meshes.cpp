// One glTF primitive → validated, fully attributed triangle list appended to the Scene.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"
#include "scene/tangents.hpp"

#include <cmath>
#include <iostream>

namespace ppr::scene::detail {

namespace {

bool finite(const float* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

// Strips and fans become lists (glTF spec 3.7.2.1 vertex orders); lists pass through.
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& in, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return in;
    std::vector<uint32_t> out;
    for (size_t i = 0; i + 2 < in.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            out.insert(out.end(), {in[i], in[i + 1 + i % 2], in[i + 2 - i % 2]});
        else  // fan
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
    }
    return out;
}

struct PrimitiveReader {
    const GltfFile& file;
    const tinygltf::Primitive& prim;
    std::string what;  // "mesh 'Cube' primitive 0"

    [[noreturn]] void bad(const std::string& problem) const { fail(file.name + ": " + what + ": " + problem); }

    // The attribute's view with its count checked against POSITION's; nullopt-like empty when absent.
    bool attribute(const char* name, AccessorKind kind, size_t vertexCount, AccessorView& out) const {
        auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return false;
        out = viewAccessor(file, it->second, kind, what + ": " + name);
        if (out.count != vertexCount)
            bad(std::string(name) + ": count " + std::to_string(out.count) + " differs from POSITION count " +
                std::to_string(vertexCount));
        return true;
    }
};

}  // namespace

int loadPrimitive(const GltfFile& file, int meshIndex, int primIndex, Scene& scene) {
    const tinygltf::Mesh& gm = file.model.meshes[size_t(meshIndex)];
    const tinygltf::Primitive& prim = gm.primitives[size_t(primIndex)];
    const std::string meshName = gm.name.empty() ? "mesh" + std::to_string(meshIndex) : gm.name;
    PrimitiveReader in{file, prim, "mesh '" + meshName + "' primitive " + std::to_string(primIndex)};

    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
        mode == TINYGLTF_MODE_LINE_STRIP) {
        std::cerr << file.name << ": " << in.what << ": points/lines (mode " << mode << ") are not drawn, skipped\n";
        return -1;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        in.bad("unknown primitive mode " + std::to_string(mode));
    if (prim.material >= 0 && size_t(prim.material) >= file.model.materials.size())
        in.bad("material " + std::to_string(prim.material) + " out of range (" +
               std::to_string(file.model.materials.size()) + " materials)");

    auto posIt = prim.attributes.find("POSITION");
    if (posIt == prim.attributes.end()) in.bad("POSITION: missing (required)");
    const AccessorView pos = viewAccessor(file, posIt->second, AccessorKind::Vec3Float, in.what + ": POSITION");
    const size_t n = pos.count;
    AccessorView nrm, uv, tan, color;
    const bool hasNormal = in.attribute("NORMAL", AccessorKind::Vec3Float, n, nrm);
    const bool hasUv = in.attribute("TEXCOORD_0", AccessorKind::TexCoord, n, uv);
    const bool hasColor = in.attribute("COLOR_0", AccessorKind::Color, n, color);
    const bool hasTangent = hasNormal && in.attribute("TANGENT", AccessorKind::Vec4Float, n, tan);  // ignored without normals (spec)

    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
        const AccessorView idx = viewAccessor(file, prim.indices, AccessorKind::Index, in.what + ": indices");
        indices.resize(idx.count);
        for (size_t i = 0; i < idx.count; ++i) {
            indices[i] = readIndex(idx, i);
            if (indices[i] >= n)
                in.bad("indices: index " + std::to_string(indices[i]) + " at position " + std::to_string(i) +
                       " out of range (vertex count " + std::to_string(n) + ")");
        }
    } else {
        indices.resize(n);
        for (size_t i = 0; i < n; ++i) indices[i] = uint32_t(i);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        in.bad(std::string(prim.indices >= 0 ? "indices: count " : "POSITION: vertex count ") +
               std::to_string(indices.size()) + " is not a multiple of 3");
    indices = toTriangleList(indices, mode);
    if (n == 0 || indices.empty()) return -1;  // nothing to draw

    auto checkSize = [&](size_t vertexCount, size_t indexCount) {
        if (scene.vertices.size() + vertexCount > kMaxElements || scene.indices.size() + indexCount > kMaxElements)
            fail(file.name + ": scene too large: more than " + std::to_string(kMaxElements) +
                 " vertices or indices (at " + in.what + ")");
    };
    checkSize(n, indices.size());  // before allocating
    std::vector<Vertex> vertices(n);
    for (size_t i = 0; i < n; ++i) {
        Vertex& v = vertices[i];
        readFloats(pos, i, &v.position.x);
        if (!finite(&v.position.x, 3)) in.bad("POSITION contains non-finite values (vertex " + std::to_string(i) + ")");
        v.uv0 = glm::vec2(0.0f);
        if (hasUv) {
            readFloats(uv, i, &v.uv0.x);
            if (!finite(&v.uv0.x, 2)) in.bad("TEXCOORD_0 contains non-finite values (vertex " + std::to_string(i) + ")");
        }
        if (hasColor) {
            glm::vec4 c(1.0f);  // VEC3 colours are opaque
            readFloats(color, i, &c.x);
            if (!finite(&c.x, color.components)) in.bad("COLOR_0 contains non-finite values (vertex " + std::to_string(i) + ")");
            v.color = glm::u16vec4(glm::round(glm::clamp(c, 0.0f, 1.0f) * 65535.0f));
        }
        if (hasNormal) {
            readFloats(nrm, i, &v.normal.x);
            const float len = glm::length(v.normal);
            // Zero or NaN normals would shade (and reflect) garbage: reject rather than guess.
            if (!std::isfinite(len) || len < 1e-6f)
                in.bad("NORMAL contains zero-length or non-finite vectors (vertex " + std::to_string(i) + ")");
            v.normal /= len;
        }
        if (hasTangent) {
            readFloats(tan, i, &v.tangent.x);
            if (!finite(&v.tangent.x, 4)) in.bad("TANGENT contains non-finite values (vertex " + std::to_string(i) + ")");
            glm::vec3 t = glm::vec3(v.tangent) - v.normal * glm::dot(v.normal, glm::vec3(v.tangent));
            const float len = glm::length(t);
            t = len > 1e-6f ? t / len : anyOrthogonal(v.normal);  // exporters emit zero tangents on UV seams
            v.tangent = glm::vec4(t, v.tangent.w < 0.0f ? -1.0f : 1.0f);
        }
    }
    if (!hasNormal) generateFlatNormals(vertices, indices);
    if (!hasTangent) generateTangents(vertices, indices);

    checkSize(vertices.size(), indices.size());  // flat normals may have un-indexed the mesh

    Mesh mesh;
    mesh.name = gm.primitives.size() == 1 ? meshName : meshName + "/" + std::to_string(primIndex);
    mesh.firstIndex = uint32_t(scene.indices.size());
    mesh.indexCount = uint32_t(indices.size());
    mesh.vertexOffset = int32_t(scene.vertices.size());
    mesh.vertexColors = hasColor;
    mesh.material = prim.material;
    mesh.boundsMin = mesh.boundsMax = vertices[indices[0]].position;
    for (uint32_t i : indices) {
        mesh.boundsMin = glm::min(mesh.boundsMin, vertices[i].position);
        mesh.boundsMax = glm::max(mesh.boundsMax, vertices[i].position);
    }
    scene.vertices.insert(scene.vertices.end(), vertices.begin(), vertices.end());
    scene.indices.insert(scene.indices.end(), indices.begin(), indices.end());
    scene.meshes.push_back(std::move(mesh));
    return int(scene.meshes.size() - 1);
}

}  // namespace ppr::scene::detail
