// glTF materials → Scene::materials (1:1 by index), referenced images → RGBA8 Scene::textures.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <cmath>

namespace ppr::scene::detail {

namespace {

constexpr size_t kMaxTexels = size_t(1) << 28;  // 16k x 16k; more is not a texture but an attack

// Decoded image (any of 1-4 channels, 8 or 16 bits, as tinygltf/stb produced it) → RGBA8.
TextureImage toRgba8(const tinygltf::Image& img, const std::string& what) {
    const size_t w = size_t(std::max(img.width, 0)), h = size_t(std::max(img.height, 0));
    const int comp = img.component, bytes = img.bits / 8;
    if (img.image.empty() || w == 0 || h == 0) fail(what + ": failed to load (no decoded pixels)");
    if (w * h > kMaxTexels) fail(what + ": " + std::to_string(w) + "x" + std::to_string(h) + " is too large");
    if (comp < 1 || comp > 4 || (img.bits != 8 && img.bits != 16))
        fail(what + ": unsupported pixel format (" + std::to_string(comp) + " channels, " + std::to_string(img.bits) + " bits)");
    if (img.image.size() != w * h * size_t(comp) * size_t(bytes))
        fail(what + ": decoded size " + std::to_string(img.image.size()) + " does not match " + std::to_string(w) + "x" +
             std::to_string(h));

    TextureImage out;
    out.width = uint32_t(w);
    out.height = uint32_t(h);
    out.rgba8.resize(w * h * 4);
    for (size_t p = 0; p < w * h; ++p) {
        uint8_t c[4] = {0, 0, 0, 255};
        for (int k = 0; k < comp; ++k) {
            const size_t at = (p * size_t(comp) + size_t(k)) * size_t(bytes);
            // 16-bit: high byte on little-endian storage, rounded (v / 257).
            c[k] = bytes == 1 ? img.image[at] : uint8_t((unsigned(img.image[at]) | unsigned(img.image[at + 1]) << 8) / 257u);
        }
        if (comp == 1 || comp == 2) {  // grey (+alpha)
            c[3] = comp == 2 ? c[1] : 255;
            c[1] = c[2] = c[0];
        }
        for (int k = 0; k < 4; ++k) out.rgba8[p * 4 + size_t(k)] = c[k];
    }
    return out;
}

struct TextureCache {
    const GltfFile& file;
    Scene& scene;
    std::map<std::pair<int, bool>, int> slots;  // (image, srgb) → Scene::textures index

    int get(int textureIndex, bool srgb, const std::string& what) {
        if (textureIndex < 0) return -1;
        const auto& m = file.model;
        if (size_t(textureIndex) >= m.textures.size())
            fail(what + ": texture " + std::to_string(textureIndex) + " out of range (" + std::to_string(m.textures.size()) + " textures)");
        const int source = m.textures[size_t(textureIndex)].source;
        if (source < 0 || size_t(source) >= m.images.size())
            fail(what + ": texture " + std::to_string(textureIndex) + " has no usable image (source " + std::to_string(source) + ")");
        if (auto it = slots.find({source, srgb}); it != slots.end()) return it->second;
        const tinygltf::Image& img = m.images[size_t(source)];
        std::string name = !img.name.empty() ? img.name : !img.uri.empty() && img.uri.rfind("data:", 0) != 0 ? img.uri
                                                                                                      : "image" + std::to_string(source);
        TextureImage tex = toRgba8(img, what + ": image " + std::to_string(source) + " '" + name + "'");
        tex.name = std::move(name);
        tex.srgb = srgb;
        scene.textures.push_back(std::move(tex));
        return slots[{source, srgb}] = int(scene.textures.size() - 1);
    }
};

}  // namespace

void loadMaterials(const GltfFile& file, Scene& scene) {
    TextureCache textures{file, scene, {}};
    const auto& materials = file.model.materials;
    for (size_t i = 0; i < materials.size(); ++i) {
        const tinygltf::Material& gm = materials[i];
        const auto& pbr = gm.pbrMetallicRoughness;
        Material mat;
        mat.name = gm.name.empty() ? "material" + std::to_string(i) : gm.name;
        const std::string what = file.name + ": material '" + mat.name + "'";
        if (pbr.baseColorFactor.size() == 4)
            mat.baseColorFactor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
        else if (!pbr.baseColorFactor.empty())
            fail(what + ": baseColorFactor: expected 4 numbers");
        mat.metallicFactor = float(pbr.metallicFactor);
        mat.roughnessFactor = float(pbr.roughnessFactor);
        mat.normalScale = float(gm.normalTexture.scale);
        const float factors[] = {mat.baseColorFactor.r, mat.baseColorFactor.g, mat.baseColorFactor.b, mat.baseColorFactor.a,
                                 mat.metallicFactor, mat.roughnessFactor, mat.normalScale};
        for (float f : factors)
            if (!std::isfinite(f)) fail(what + ": non-finite factor");

        mat.baseColorTexture = textures.get(pbr.baseColorTexture.index, true, what + " baseColorTexture");
        mat.normalTexture = textures.get(gm.normalTexture.index, false, what + " normalTexture");
        mat.metallicRoughnessTexture = textures.get(pbr.metallicRoughnessTexture.index, false, what + " metallicRoughnessTexture");

        if (gm.extras.Has("ppr_reflective")) {
            const tinygltf::Value& flag = gm.extras.Get("ppr_reflective");
            if (!flag.IsBool()) fail(what + ": extras.ppr_reflective: expected true or false");
            mat.reflective = flag.Get<bool>();
        }
        mat.transparent = gm.alphaMode == "BLEND";
        scene.materials.push_back(std::move(mat));
    }
}

}  // namespace ppr::scene::detail
