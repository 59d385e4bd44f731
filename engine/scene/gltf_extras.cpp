// glTF extras: reflectors authored on nodes (extras.ppr_reflector, in the node's local space).
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <cmath>

namespace ppr::scene::detail {

nlohmann::json toJson(const tinygltf::Value& v) {
    using nlohmann::json;
    if (v.IsBool()) return v.Get<bool>();
    if (v.IsInt()) return v.Get<int>();
    if (v.IsReal()) return v.Get<double>();
    if (v.IsString()) return v.Get<std::string>();
    if (v.IsArray()) {
        json a = json::array();
        for (const auto& e : v.Get<tinygltf::Value::Array>()) a.push_back(toJson(e));
        return a;
    }
    if (v.IsObject()) {
        json o = json::object();
        for (const auto& [key, e] : v.Get<tinygltf::Value::Object>()) o[key] = toJson(e);
        return o;
    }
    return nullptr;  // null and binary
}

std::string nodeLabel(const GltfFile& file, int node) {
    const std::string& name = file.model.nodes[size_t(node)].name;
    return name.empty() ? "node " + std::to_string(node) : "node '" + name + "'";
}

bool nodeReflector(const GltfFile& file, int node, const glm::mat4& world, Reflector& out) {
    const tinygltf::Node& n = file.model.nodes[size_t(node)];
    if (!n.extras.Has("ppr_reflector")) return false;
    const std::string where = file.name + ": " + nodeLabel(file, node) + " extras.ppr_reflector";
    nlohmann::json j = toJson(n.extras.Get("ppr_reflector"));
    if (j.is_object() && !j.contains("name")) j["name"] = n.name.empty() ? "node" + std::to_string(node) : n.name;
    const Reflector local = parseReflector(j, where);  // validated in local space first

    // Points by the world matrix, the normal by its inverse transpose; extents scale with the
    // lengths of the transformed tangent and bitangent (so node scale resizes the rectangle).
    const glm::mat3 m(world);
    const glm::vec3 t = m * local.tangent;
    const glm::vec3 b = m * local.bitangent();
    glm::vec3 normal = glm::transpose(glm::inverse(m)) * local.normal;
    out = local;
    out.center = glm::vec3(world * glm::vec4(local.center, 1.0f));
    const float nl = glm::length(normal), tl = glm::length(t);
    if (!(nl > 0.0f) || !(tl > 0.0f) || !std::isfinite(nl) || !std::isfinite(tl) || std::abs(glm::determinant(m)) < 1e-12f)
        fail(where + ": node transform is degenerate (zero scale?)");
    out.normal = normal / nl;
    const glm::vec3 tw = t - out.normal * glm::dot(out.normal, t);  // exact in theory; removes rounding
    out.tangent = glm::normalize(tw);
    out.halfExtents = local.halfExtents * glm::vec2(tl, glm::length(b));
    if (auto problem = validateReflector(out); !problem.empty()) fail(where + "." + problem + " (after the node transform)");
    return true;
}

}  // namespace ppr::scene::detail
