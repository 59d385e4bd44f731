// glTF materials → Scene::materials (1:1 by index), referenced images → RGBA8 Scene::textures.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

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
        const int source = sourceOf(textureIndex, what);
        if (auto it = slots.find({source, srgb}); it != slots.end()) return it->second;
        TextureImage tex = decode(textureIndex, what);
        tex.srgb = srgb;
        scene.textures.push_back(std::move(tex));
        return slots[{source, srgb}] = int(scene.textures.size() - 1);
    }

    // The texture's image decoded to RGBA8 and named, without adding it to the scene (for textures a
    // material derives from it, such as a roughness texture from a specular-glossiness one).
    TextureImage decode(int textureIndex, const std::string& what) const {
        const int source = sourceOf(textureIndex, what);
        const tinygltf::Image& img = file.model.images[size_t(source)];
        std::string name = !img.name.empty() ? img.name : !img.uri.empty() && img.uri.rfind("data:", 0) != 0 ? img.uri
                                                                                                      : "image" + std::to_string(source);
        TextureImage tex = toRgba8(img, what + ": image " + std::to_string(source) + " '" + name + "'");
        tex.name = std::move(name);
        return tex;
    }

private:
    int sourceOf(int textureIndex, const std::string& what) const {
        const auto& m = file.model;
        if (textureIndex < 0 || size_t(textureIndex) >= m.textures.size())
            fail(what + ": texture " + std::to_string(textureIndex) + " out of range (" + std::to_string(m.textures.size()) + " textures)");
        const int source = m.textures[size_t(textureIndex)].source;
        if (source < 0 || size_t(source) >= m.images.size())
            fail(what + ": texture " + std::to_string(textureIndex) + " has no usable image (source " + std::to_string(source) + ")");
        return source;
    }
};

// KHR_materials_pbrSpecularGlossiness (older exporters, assimp among them, still write it) as metal/rough,
// the way Khronos' converter does it for the factors: roughness = 1 − glossiness; metallic from the
// diffuse and specular brightness; base colour blended between the diffuse and specular readings.
// The diffuse texture becomes the base colour texture; a specular-glossiness texture becomes a
// roughness texture (G = 1 − glossiness · A), its specular colour ignored.
float perceivedBrightness(const glm::vec3& c) { return std::sqrt(0.299f * c.r * c.r + 0.587f * c.g * c.g + 0.114f * c.b * c.b); }

float solveMetallic(float diffuse, float specular, float oneMinusSpecularStrength) {
    constexpr float kDielectricSpecular = 0.04f;
    if (specular < kDielectricSpecular) return 0.0f;
    const float a = kDielectricSpecular;
    const float b = diffuse * oneMinusSpecularStrength / (1.0f - kDielectricSpecular) + specular - 2.0f * kDielectricSpecular;
    const float c = kDielectricSpecular - specular;
    const float d = std::max(b * b - 4.0f * a * c, 0.0f);
    return std::clamp((-b + std::sqrt(d)) / (2.0f * a), 0.0f, 1.0f);
}

std::vector<double> numbers(const tinygltf::Value& object, const char* key, size_t count, const std::string& what) {
    if (!object.Has(key)) return {};
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsArray() || v.ArrayLen() != count) fail(what + ": " + key + ": expected " + std::to_string(count) + " numbers");
    std::vector<double> out;
    for (size_t i = 0; i < count; ++i) {
        if (!v.Get(int(i)).IsNumber()) fail(what + ": " + key + ": expected " + std::to_string(count) + " numbers");
        out.push_back(v.Get(int(i)).GetNumberAsDouble());
    }
    return out;
}

int textureIndex(const tinygltf::Value& object, const char* key, const std::string& what) {
    if (!object.Has(key)) return -1;
    const tinygltf::Value& t = object.Get(key);
    if (!t.IsObject() || !t.Has("index") || !t.Get("index").IsInt()) fail(what + ": " + key + ": expected {\"index\": N}");
    return t.Get("index").Get<int>();
}

void applySpecularGlossiness(const tinygltf::Value& ext, Material& mat, TextureCache& textures, Scene& scene, const std::string& what) {
    if (!ext.IsObject()) fail(what + ": expected an object");
    const std::vector<double> d = numbers(ext, "diffuseFactor", 4, what), sp = numbers(ext, "specularFactor", 3, what);
    const glm::vec4 diffuse = d.empty() ? glm::vec4(1.0f) : glm::vec4(float(d[0]), float(d[1]), float(d[2]), float(d[3]));
    const glm::vec3 specular = sp.empty() ? glm::vec3(1.0f) : glm::vec3(float(sp[0]), float(sp[1]), float(sp[2]));
    const float glossiness = ext.Has("glossinessFactor") && ext.Get("glossinessFactor").IsNumber()
                                 ? float(ext.Get("glossinessFactor").GetNumberAsDouble())
                                 : 1.0f;
    for (float f : {diffuse.r, diffuse.g, diffuse.b, diffuse.a, specular.r, specular.g, specular.b, glossiness})
        if (!std::isfinite(f)) fail(what + ": non-finite factor");
    const float specularStrength = std::max({specular.r, specular.g, specular.b});
    const float metallic = solveMetallic(perceivedBrightness(glm::vec3(diffuse)), perceivedBrightness(specular), 1.0f - specularStrength);
    const glm::vec3 fromDiffuse = glm::vec3(diffuse) * (1.0f - specularStrength) / (1.0f - 0.04f) / std::max(1.0f - metallic, 1e-4f);
    const glm::vec3 fromSpecular = (specular - glm::vec3(0.04f * (1.0f - metallic))) / std::max(metallic, 1e-4f);
    mat.baseColorFactor = glm::vec4(glm::clamp(glm::mix(fromDiffuse, fromSpecular, metallic * metallic), 0.0f, 1.0f), diffuse.a);
    mat.metallicFactor = metallic;
    mat.roughnessFactor = std::clamp(1.0f - glossiness, 0.0f, 1.0f);
    mat.baseColorTexture = textures.get(textureIndex(ext, "diffuseTexture", what), true, what + " diffuseTexture");
    mat.metallicRoughnessTexture = -1;
    if (const int sg = textureIndex(ext, "specularGlossinessTexture", what); sg >= 0) {
        // Decoded linear, then rewritten per texel: roughness in G, metallic (the factor) in B.
        TextureImage rough = textures.decode(sg, what + " specularGlossinessTexture");
        rough.name += " (roughness from glossiness)";
        rough.srgb = false;
        for (size_t p = 0; p < size_t(rough.width) * rough.height; ++p) {
            const float gloss = glossiness * float(rough.rgba8[p * 4 + 3]) / 255.0f;
            rough.rgba8[p * 4 + 0] = 255;
            rough.rgba8[p * 4 + 1] = uint8_t(std::lround(255.0f * std::clamp(1.0f - gloss, 0.0f, 1.0f)));
            rough.rgba8[p * 4 + 2] = 255;
            rough.rgba8[p * 4 + 3] = 255;
        }
        scene.textures.push_back(std::move(rough));
        mat.metallicRoughnessTexture = int(scene.textures.size() - 1);
        mat.roughnessFactor = 1.0f;  // the texture holds it
    }
}

// KHR_texture_transform of one textureInfo as the rows of uv' = T·R·S·(uv, 1) (the extension's
// matrix: rotation counter-clockwise in UV space), or nothing when the textureInfo has none.
struct UvTransform {
    glm::vec3 row0{1.0f, 0.0f, 0.0f}, row1{0.0f, 1.0f, 0.0f};
    bool operator==(const UvTransform&) const = default;
};
std::optional<UvTransform> textureTransform(const tinygltf::ExtensionMap& extensions, const std::string& what) {
    const auto it = extensions.find("KHR_texture_transform");
    if (it == extensions.end()) return std::nullopt;
    const std::string where = what + " KHR_texture_transform";
    const tinygltf::Value& t = it->second;
    if (!t.IsObject()) fail(where + ": expected an object");
    const std::vector<double> offset = numbers(t, "offset", 2, where), scale = numbers(t, "scale", 2, where);
    const double rotation = t.Has("rotation") && t.Get("rotation").IsNumber() ? t.Get("rotation").GetNumberAsDouble() : 0.0;
    const glm::vec2 o = offset.empty() ? glm::vec2(0.0f) : glm::vec2(float(offset[0]), float(offset[1]));
    const glm::vec2 s = scale.empty() ? glm::vec2(1.0f) : glm::vec2(float(scale[0]), float(scale[1]));
    for (float f : {o.x, o.y, s.x, s.y, float(rotation)})
        if (!std::isfinite(f)) fail(where + ": non-finite value");
    if (t.Has("texCoord") && t.Get("texCoord").IsInt() && t.Get("texCoord").Get<int>() != 0)
        std::cerr << where << ": texCoord " << t.Get("texCoord").Get<int>() << " ignored (only TEXCOORD_0 is read)\n";
    const float c = float(std::cos(rotation)), sn = float(std::sin(rotation));
    return UvTransform{{c * s.x, sn * s.y, o.x}, {-sn * s.x, c * s.y, o.y}};
}

// KHR_materials_emissive_strength: the factor that lets emissiveFactor exceed 1 (HDR emitters).
float emissiveStrength(const tinygltf::ExtensionMap& extensions, const std::string& what) {
    const auto it = extensions.find("KHR_materials_emissive_strength");
    if (it == extensions.end()) return 1.0f;
    const std::string where = what + " KHR_materials_emissive_strength";
    const tinygltf::Value& e = it->second;
    if (!e.IsObject()) fail(where + ": expected an object");
    if (!e.Has("emissiveStrength")) return 1.0f;
    const tinygltf::Value& s = e.Get("emissiveStrength");
    const double strength = s.IsNumber() ? s.GetNumberAsDouble() : -1.0;
    if (!(strength >= 0.0) || !std::isfinite(strength)) fail(where + ": emissiveStrength: expected a finite number >= 0");
    return float(strength);
}

}  // namespace

bool isSupportedExtension(const std::string& name) {
    static constexpr const char* kSupported[] = {"KHR_materials_emissive_strength", "KHR_materials_pbrSpecularGlossiness",
                                                 "KHR_texture_transform"};
    for (const char* s : kSupported)
        if (name == s) return true;
    return false;
}

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

        if (gm.emissiveFactor.size() == 3)
            mat.emissiveFactor = glm::vec3(gm.emissiveFactor[0], gm.emissiveFactor[1], gm.emissiveFactor[2]);
        else if (!gm.emissiveFactor.empty())
            fail(what + ": emissiveFactor: expected 3 numbers");
        if (!std::isfinite(mat.emissiveFactor.r) || !std::isfinite(mat.emissiveFactor.g) || !std::isfinite(mat.emissiveFactor.b) ||
            glm::any(glm::lessThan(mat.emissiveFactor, glm::vec3(0.0f))))
            fail(what + ": emissiveFactor: expected finite numbers >= 0");
        mat.emissiveFactor *= emissiveStrength(gm.extensions, what);

        mat.baseColorTexture = textures.get(pbr.baseColorTexture.index, true, what + " baseColorTexture");
        if (mat.emissiveFactor != glm::vec3(0.0f))  // a texture under a zero factor emits nothing: not decoded
            mat.emissiveTexture = textures.get(gm.emissiveTexture.index, true, what + " emissiveTexture");
        mat.normalTexture = textures.get(gm.normalTexture.index, false, what + " normalTexture");
        mat.metallicRoughnessTexture = textures.get(pbr.metallicRoughnessTexture.index, false, what + " metallicRoughnessTexture");

        // One transform per material: the first textureInfo's that has one; a different one on another
        // texture is reported and not applied.
        std::optional<UvTransform> uv;
        const std::pair<const tinygltf::ExtensionMap*, const char*> infos[] = {{&pbr.baseColorTexture.extensions, "baseColorTexture"},
                                                                               {&pbr.metallicRoughnessTexture.extensions, "metallicRoughnessTexture"},
                                                                               {&gm.normalTexture.extensions, "normalTexture"},
                                                                               {&gm.emissiveTexture.extensions, "emissiveTexture"}};
        for (const auto& [extensions, slot] : infos)
            if (std::optional<UvTransform> t = textureTransform(*extensions, what + " " + slot)) {
                if (!uv) uv = t;
                else if (!(*t == *uv)) std::cerr << what << " " << slot << ": KHR_texture_transform differs from the material's first one; that one is used\n";
            }
        if (uv) {
            mat.uvRow0 = uv->row0;
            mat.uvRow1 = uv->row1;
        }

        if (const auto ext = gm.extensions.find("KHR_materials_pbrSpecularGlossiness"); ext != gm.extensions.end())
            applySpecularGlossiness(ext->second, mat, textures, scene, what + " KHR_materials_pbrSpecularGlossiness");

        if (gm.extras.Has("ppr_reflective")) {
            const tinygltf::Value& flag = gm.extras.Get("ppr_reflective");
            if (!flag.IsBool()) fail(what + ": extras.ppr_reflective: expected true or false");
            mat.reflective = flag.Get<bool>();
        }
        mat.transparent = gm.alphaMode == "BLEND";
        mat.masked = gm.alphaMode == "MASK";
        if (mat.masked) {
            mat.alphaCutoff = float(gm.alphaCutoff);
            if (!(mat.alphaCutoff >= 0.0f) || !std::isfinite(mat.alphaCutoff))
                fail(what + ": alphaCutoff: expected a finite number >= 0, got " + std::to_string(gm.alphaCutoff));
        }
        scene.materials.push_back(std::move(mat));
    }
}

}  // namespace ppr::scene::detail
