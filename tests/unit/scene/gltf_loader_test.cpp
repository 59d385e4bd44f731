// loadGltf on the hand-written test scene (tests/data/gltf/quad_scene.*) and on broken variants of it.
#include "scene/scene.hpp"

#include "test_util.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>

using namespace ppr::scene;
using ppr::scene::test::dataPath;
using ppr::scene::test::expectError;
using ppr::scene::test::readText;
using ppr::scene::test::TempDir;
using ppr::scene::test::writeText;
using nlohmann::json;

namespace {

void expectVec(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

const DrawItem& drawOf(const Scene& s, const std::string& node) {
    for (const auto& d : s.draws)
        if (d.nodeName == node) return d;
    throw std::runtime_error("no draw for node " + node);
}

// Checks the scene described in quad_scene.gltf's asset.extras.description.
void expectQuadScene(const Scene& s) {
    EXPECT_EQ(s.meshes.size(), 2u);  // the reflective quad is shared by three nodes
    EXPECT_EQ(s.draws.size(), 4u);
    EXPECT_EQ(s.vertices.size(), 4u + 6u);  // PlainQuad had no normals: flat, un-indexed
    EXPECT_EQ(s.indices.size(), 12u);
    EXPECT_EQ(s.materials.size(), 2u);

    ASSERT_EQ(s.cameras.size(), 1u);
    const NamedCamera* cam = s.findCamera("MainCam");
    ASSERT_NE(cam, nullptr);
    expectVec(cam->pose.position, {1, 2, 5});
    EXPECT_NEAR(cam->pose.yawDeg, 30.0f, 1e-3f);
    EXPECT_NEAR(cam->pose.pitchDeg, -20.0f, 1e-3f);
    EXPECT_NEAR(cam->pose.fovYDeg, 50.0f, 1e-3f);
    EXPECT_EQ(s.findCamera("nope"), nullptr);

    ASSERT_EQ(s.reflectors.size(), 2u);
    const Reflector& floor = s.reflectors[0];
    EXPECT_EQ(floor.name, "Floor");  // defaults to the node name
    expectVec(floor.center, {0, 0.5f, 0});
    expectVec(floor.normal, {0, 1, 0});
    expectVec(floor.tangent, {1, 0, 0});
    EXPECT_NEAR(floor.halfExtents.x, 2.0f, 1e-5f);  // node scale (2, 1, 3)
    EXPECT_NEAR(floor.halfExtents.y, 3.0f, 1e-5f);
    EXPECT_NEAR(floor.reflectance, 0.8f, 1e-6f);
    EXPECT_EQ(floor.kind, ReflectorKind::Opaque);

    // Ramp: local normal +Y under parent scale (2,1,1) · R_z(45°); normal by the inverse transpose.
    const Reflector& ramp = s.reflectors[1];
    EXPECT_EQ(ramp.name, "RampMirror");
    EXPECT_EQ(ramp.kind, ReflectorKind::Glass);
    expectVec(ramp.normal, glm::normalize(glm::vec3(-0.5f, 1, 0)));
    expectVec(ramp.tangent, glm::normalize(glm::vec3(2, 1, 0)));
    EXPECT_NEAR(ramp.halfExtents.x, std::sqrt(2.5f), 1e-4f);
    EXPECT_NEAR(ramp.halfExtents.y, 0.5f, 1e-5f);
    EXPECT_NEAR(glm::dot(ramp.normal, ramp.tangent), 0.0f, 1e-6f);

    EXPECT_EQ(drawOf(s, "Floor").reflector, 0);  // node extras
    EXPECT_EQ(drawOf(s, "Ramp").reflector, 1);
    EXPECT_EQ(drawOf(s, "Tile").reflector, 0);   // geometric: inside Floor's rectangle, reflective material
    EXPECT_EQ(drawOf(s, "Plain").reflector, -1);
    expectVec(glm::vec3(drawOf(s, "Tile").world[3]), {0.5f, 0.5f, 0.5f});

    const Material& mirror = s.materials[0];
    EXPECT_TRUE(mirror.reflective);
    EXPECT_NEAR(mirror.roughnessFactor, 0.05f, 1e-6f);
    const Material& painted = s.materials[1];
    EXPECT_FALSE(painted.reflective);
    EXPECT_NEAR(painted.normalScale, 0.5f, 1e-6f);
    EXPECT_EQ(painted.baseColorFactor, glm::vec4(1, 0.5f, 0.25f, 1));
    ASSERT_EQ(s.textures.size(), 2u);  // one image, used as sRGB colour and as linear normal map
    ASSERT_GE(painted.baseColorTexture, 0);
    ASSERT_GE(painted.normalTexture, 0);
    const TextureImage& color = s.textures[size_t(painted.baseColorTexture)];
    EXPECT_TRUE(color.srgb);
    EXPECT_FALSE(s.textures[size_t(painted.normalTexture)].srgb);
    EXPECT_EQ(color.width, 2u);
    EXPECT_EQ(color.height, 2u);
    ASSERT_EQ(color.rgba8.size(), 16u);
    EXPECT_EQ(std::vector<uint8_t>(color.rgba8.begin(), color.rgba8.begin() + 8), (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));
    EXPECT_EQ(painted.metallicRoughnessTexture, -1);

    // Floor spans x ±2, z ±3; Ramp dips to y = -sin45; Plain sits at y = 3.
    expectVec(s.boundsMin, {-2, -0.70711f, -3});
    expectVec(s.boundsMax, {2, 3, 3});

    for (const Vertex& v : s.vertices) {
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-5f);
        EXPECT_TRUE(v.tangent.w == 1.0f || v.tangent.w == -1.0f);
    }
    for (const Mesh& m : s.meshes)
        for (uint32_t i = 0; i < m.indexCount; ++i) EXPECT_LT(m.vertexOffset + s.indices[m.firstIndex + i], s.vertices.size());
}

// The test scene's JSON, for building broken variants of it.
json quadJson() { return json::parse(readText(dataPath("gltf/quad_scene.gltf"))); }

std::string writeGltf(const TempDir& dir, const json& doc, const std::string& name = "broken.gltf") {
    const std::string path = dir.file(name);
    writeText(path, doc.dump(1));
    return path;
}

// Minimal base64 so a test can poke bytes into the embedded buffer.
const char* kB64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
std::vector<uint8_t> unbase64(const std::string& s) {
    std::vector<uint8_t> out;
    uint32_t acc = 0;
    int bits = 0;
    for (char c : s) {
        const char* p = std::strchr(kB64, c);
        if (!p || c == 0) continue;
        acc = (acc << 6) | uint32_t(p - kB64);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(uint8_t(acc >> bits));
        }
    }
    return out;
}
std::string base64(const std::vector<uint8_t>& in) {
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        const size_t left = in.size() - i;
        uint32_t n = uint32_t(in[i]) << 16;
        if (left > 1) n |= uint32_t(in[i + 1]) << 8;
        if (left > 2) n |= in[i + 2];
        out += kB64[(n >> 18) & 63];
        out += kB64[(n >> 12) & 63];
        out += left > 1 ? kB64[(n >> 6) & 63] : '=';
        out += left > 2 ? kB64[n & 63] : '=';
    }
    return out;
}

}  // namespace

TEST(Gltf, LoadsHandWrittenScene) {
    const std::string path = dataPath("gltf/quad_scene.gltf");
    const Scene s = loadGltf(path);
    EXPECT_EQ(s.sourcePath, path);
    expectQuadScene(s);
}

TEST(Gltf, LoadsBinaryVersion) { expectQuadScene(loadGltf(dataPath("gltf/quad_scene.glb"))); }

TEST(Gltf, SidecarReflectorsReplaceExtras) {
    TempDir dir;
    writeText(dir.file("scene.gltf"), readText(dataPath("gltf/quad_scene.gltf")));
    Reflector plain;
    plain.name = "Plain";  // binds the node of the same name
    plain.center = {0, 3, 0};
    plain.halfExtents = {1, 1};
    saveReflectorFileAtomic(dir.file("scene.reflectors.json"), {plain});
    Scene s = loadGltf(dir.file("scene.gltf"));
    ASSERT_EQ(s.reflectors.size(), 1u);
    EXPECT_EQ(s.reflectors[0].name, "Plain");
    EXPECT_EQ(drawOf(s, "Plain").reflector, 0);
    EXPECT_EQ(drawOf(s, "Floor").reflector, -1);  // extras ignored; Floor is not on the y = 3 plane

    // An explicit file wins over the sidecar.
    Reflector floor;
    floor.name = "Floor";
    floor.center = {0, 0.5f, 0};
    floor.halfExtents = {2, 3};
    Reflector other = floor;
    other.name = "Other";
    saveReflectorFileAtomic(dir.file("explicit.json"), {other, floor});
    s = loadGltf(dir.file("scene.gltf"), LoadOptions{dir.file("explicit.json")});
    ASSERT_EQ(s.reflectors.size(), 2u);
    EXPECT_EQ(drawOf(s, "Floor").reflector, 1);  // by name
    EXPECT_EQ(drawOf(s, "Tile").reflector, 0);   // by geometry: first matching reflector
    EXPECT_EQ(drawOf(s, "Plain").reflector, -1);

    // A broken sidecar is an error naming the sidecar.
    writeText(dir.file("scene.reflectors.json"), R"({"version":1,"reflectors":[{"name":"x"}]})");
    expectError([&] { loadGltf(dir.file("scene.gltf")); }, {"scene.reflectors.json", "reflectors[0].center: missing"});
    expectError([&] { loadGltf(dir.file("scene.gltf"), LoadOptions{dir.file("missing.json")}); }, {"missing.json", "no such file"});
}

TEST(Gltf, MissingAndBrokenFiles) {
    expectError([] { loadGltf("/nonexistent/scene.gltf"); }, {"/nonexistent/scene.gltf", "no such file"});
    TempDir dir;
    writeText(dir.file("truncated.gltf"), readText(dataPath("gltf/quad_scene.gltf")).substr(0, 300));
    expectError([&] { loadGltf(dir.file("truncated.gltf")); }, {"truncated.gltf"});
    const std::string glb = readText(dataPath("gltf/quad_scene.glb"));
    writeText(dir.file("truncated.glb"), glb.substr(0, glb.size() / 2));
    expectError([&] { loadGltf(dir.file("truncated.glb")); }, {"truncated.glb"});
    writeText(dir.file("empty.gltf"), "");
    expectError([&] { loadGltf(dir.file("empty.gltf")); }, {"empty.gltf"});
    expectError([&] { loadGltf(dir.path.string()); }, {dir.path.string(), "not a regular file"});
}

struct Variant {
    const char* name;
    void (*edit)(json&);
    std::vector<std::string> expected;
};

class BrokenGltf : public ::testing::TestWithParam<Variant> {};

TEST_P(BrokenGltf, RejectedWithOneLineNamingFileAndPlace) {
    TempDir dir;
    json doc = quadJson();
    GetParam().edit(doc);
    const std::string path = writeGltf(dir, doc);
    std::vector<std::string> parts = GetParam().expected;
    parts.push_back(path);
    expectError([&] { loadGltf(path); }, parts);
}

// Accessors in quad_scene: 0 pos, 1 normal, 2 uv, 3 indices (ReflectiveQuad); 4 pos, 5 uv, 6 indices (PlainQuad).
INSTANTIATE_TEST_SUITE_P(
    Cases, BrokenGltf,
    ::testing::Values(
        Variant{"AccessorPastBufferView", [](json& d) { d["accessors"][0]["count"] = 40; },
                {"mesh 'ReflectiveQuad' primitive 0: POSITION", "needs 480 bytes"}},
        Variant{"AccessorOffsetPastView", [](json& d) { d["accessors"][2]["byteOffset"] = 1000; },
                {"TEXCOORD_0", "accessor 2", "offset 1000"}},
        Variant{"BufferViewPastBuffer", [](json& d) { d["bufferViews"][0]["byteLength"] = 100000; }, {"POSITION", "bufferView 0"}},
        Variant{"WrongPositionType", [](json& d) { d["accessors"][0]["componentType"] = 5123; },
                {"POSITION", "expected FLOAT VEC3, got UNSIGNED_SHORT VEC3"}},
        Variant{"WrongIndexType", [](json& d) { d["accessors"][3]["type"] = "VEC2"; }, {"indices", "expected SCALAR"}},
        Variant{"IntegerUvNotNormalized", [](json& d) { d["accessors"][2]["componentType"] = 5121; }, {"TEXCOORD_0", "normalized"}},
        Variant{"BadStride", [](json& d) { d["bufferViews"][0]["byteStride"] = 4; }, {"POSITION", "byteStride 4"}},
        Variant{"CountMismatch", [](json& d) { d["accessors"][4]["count"] = 2; }, {"mesh 'PlainQuad' primitive 0: TEXCOORD_0", "count 4 differs"}},
        Variant{"IndexOutOfRange",
                [](json& d) {
                    d["accessors"][4]["count"] = 2;
                    d["accessors"][5]["count"] = 2;
                },
                {"mesh 'PlainQuad' primitive 0: indices", "index 3", "out of range (vertex count 2)"}},
        Variant{"IndexCountNotTriangles", [](json& d) { d["accessors"][6]["count"] = 5; }, {"PlainQuad", "not a multiple of 3"}},
        Variant{"MissingPosition", [](json& d) { d["meshes"][1]["primitives"][0]["attributes"].erase("POSITION"); }, {"PlainQuad", "POSITION: missing"}},
        Variant{"AccessorIndexOutOfRange", [](json& d) { d["meshes"][1]["primitives"][0]["attributes"]["TEXCOORD_0"] = 99; },
                {"PlainQuad", "TEXCOORD_0", "accessor 99 out of range"}},
        Variant{"SparseIndicesNotIncreasing",  // bufferView 3 holds the quad's triangle indices, which repeat
                [](json& d) {
                    d["accessors"][0]["sparse"] = {{"count", 4},
                                                   {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
                                                   {"values", {{"bufferView", 0}}}};
                },
                {"POSITION", "sparse: index 2 (entry 2) is out of range or not increasing"}},
        Variant{"SparseValuesPastView",
                [](json& d) {
                    d["accessors"][0]["sparse"] = {{"count", 3},
                                                   {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
                                                   {"values", {{"bufferView", 3}}}};
                },
                {"POSITION", "sparse: values: needs 36 bytes"}},
        Variant{"NoBufferViewNotSparse", [](json& d) { d["accessors"][0].erase("bufferView"); }, {"POSITION", "has no bufferView and is not sparse"}},
        Variant{"MaterialOutOfRange", [](json& d) { d["meshes"][0]["primitives"][0]["material"] = 9; }, {"ReflectiveQuad", "material 9 out of range"}},
        Variant{"TextureOutOfRange", [](json& d) { d["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5; },
                {"material 'Painted' baseColorTexture", "texture 5 out of range"}},
        Variant{"TextureWithoutImage", [](json& d) { d["textures"][0].erase("source"); }, {"material 'Painted'", "no usable image"}},
        Variant{"ReflectiveNotBool", [](json& d) { d["materials"][0]["extras"]["ppr_reflective"] = "yes"; },
                {"material 'Mirror'", "extras.ppr_reflective"}},
        Variant{"MeshOutOfRange", [](json& d) { d["nodes"][4]["mesh"] = 7; }, {"node 'Plain'", "mesh 7 out of range"}},
        Variant{"ChildOutOfRange", [](json& d) { d["nodes"][4]["children"] = {42}; }, {"node 'Plain' children", "node 42 out of range"}},
        Variant{"Cycle", [](json& d) { d["nodes"][2]["children"] = {1}; }, {"node 'Scaler'", "cycle"}},
        Variant{"TwoParents", [](json& d) { d["nodes"][4]["children"] = {3}; }, {"node 'Tile'", "more than one parent"}},
        Variant{"SceneOutOfRange", [](json& d) { d["scene"] = 3; }, {"scene 3"}},
        Variant{"ZeroQuaternion", [](json& d) { d["nodes"][2]["rotation"] = {0, 0, 0, 0}; }, {"node 'Ramp'", "rotation"}},
        Variant{"ExtrasZeroNormal", [](json& d) { d["nodes"][0]["extras"]["ppr_reflector"]["normal"] = {0, 0, 0}; },
                {"node 'Floor' extras.ppr_reflector.normal: zero length"}},
        Variant{"ExtrasUnknownField", [](json& d) { d["nodes"][0]["extras"]["ppr_reflector"]["colour"] = 1; },
                {"node 'Floor' extras.ppr_reflector.colour: unknown field"}},
        Variant{"ExtrasMissingCenter", [](json& d) { d["nodes"][0]["extras"]["ppr_reflector"].erase("center"); },
                {"node 'Floor' extras.ppr_reflector.center: missing"}},
        Variant{"ExtrasZeroExtent", [](json& d) { d["nodes"][0]["extras"]["ppr_reflector"]["half_extents"] = {1, 0}; },
                {"node 'Floor' extras.ppr_reflector.half_extents: must be > 0.0001 m"}},
        Variant{"ExtrasDuplicateName", [](json& d) { d["nodes"][2]["extras"]["ppr_reflector"]["name"] = "Floor"; },
                {"node 'Ramp' extras.ppr_reflector.name", "duplicate reflector name 'Floor'"}},
        Variant{"ExtrasZeroScale", [](json& d) { d["nodes"][0]["scale"] = {0, 1, 3}; }, {"node 'Floor' extras.ppr_reflector"}},
        Variant{"CameraFov", [](json& d) { d["cameras"][0]["perspective"]["yfov"] = 3.14; }, {"node 'MainCam'", "yfov"}},
        Variant{"RequiredExtension",
                [](json& d) {
                    d["extensionsUsed"] = {"KHR_draco_mesh_compression"};
                    d["extensionsRequired"] = {"KHR_draco_mesh_compression"};
                },
                {"extensionsRequired", "KHR_draco_mesh_compression"}},
        Variant{"MissingBuffer", [](json& d) { d["buffers"][0]["uri"] = "nowhere.bin"; }, {"nowhere.bin"}}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Gltf, NonFinitePositionsRejected) {
    TempDir dir;
    json doc = quadJson();
    std::string uri = doc["buffers"][0]["uri"];
    const std::string prefix = uri.substr(0, uri.find(',') + 1);
    std::vector<uint8_t> bytes = unbase64(uri.substr(prefix.size()));
    ASSERT_EQ(base64(bytes), uri.substr(prefix.size())) << "test base64 codec broken";
    const float inf = INFINITY;
    const size_t at = doc["bufferViews"][0]["byteOffset"].get<size_t>() + 4;  // vertex 0, y
    std::memcpy(&bytes[at], &inf, 4);
    doc["buffers"][0]["uri"] = prefix + base64(bytes);
    const std::string path = writeGltf(dir, doc);
    expectError([&] { loadGltf(path); }, {path, "mesh 'ReflectiveQuad' primitive 0: POSITION contains non-finite values"});
}

// Sparse accessors (spec 3.6.2.3): vertex 2 of the reflective quad moved by a sparse substitution
// over its bufferView, and a base of zeros where the accessor has no bufferView.
TEST(Gltf, SparseAccessorsReplaceElements) {
    for (const bool zeroBase : {false, true}) {
        TempDir dir;
        json doc = quadJson();
        std::string uri = doc["buffers"][0]["uri"];
        const std::string prefix = uri.substr(0, uri.find(',') + 1);
        std::vector<uint8_t> bytes = unbase64(uri.substr(prefix.size()));
        const size_t indexAt = bytes.size();
        const uint16_t index = 2;
        bytes.resize(indexAt + 4);
        std::memcpy(&bytes[indexAt], &index, 2);
        const float value[3] = {0.25f, 5.0f, -0.5f};
        const size_t valueAt = bytes.size();
        bytes.resize(valueAt + 12);
        std::memcpy(&bytes[valueAt], value, 12);
        doc["buffers"][0]["uri"] = prefix + base64(bytes);
        doc["buffers"][0]["byteLength"] = bytes.size();
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", indexAt}, {"byteLength", 2}});
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", valueAt}, {"byteLength", 12}});
        const int views = int(doc["bufferViews"].size());
        json& positions = doc["accessors"][0];
        if (zeroBase) positions.erase("bufferView");
        positions["max"] = {1, 5, 1};
        positions["sparse"] = {{"count", 1},
                               {"indices", {{"bufferView", views - 2}, {"componentType", 5123}}},
                               {"values", {{"bufferView", views - 1}}}};
        const Scene s = loadGltf(writeGltf(dir, doc));
        const Mesh& quad = s.meshes[s.draws[0].mesh];
        SCOPED_TRACE(zeroBase ? "zero base" : "bufferView base");
        expectVec(s.vertices[size_t(quad.vertexOffset) + 2].position, {0.25f, 5.0f, -0.5f});
        const glm::vec3 first = s.vertices[size_t(quad.vertexOffset)].position;
        if (zeroBase) expectVec(first, {0, 0, 0});
        else expectVec(first, {-1, 0, -1});
    }
}

// KHR_materials_pbrSpecularGlossiness → metal/rough (Debian's assimp test model; it also carries a
// metal/rough fallback with roughness 1, which the extension overrides).
TEST(Gltf, SpecularGlossinessBecomesMetalRough) {
    const Scene s = loadGltf("/usr/share/assimp/models/glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf");
    ASSERT_EQ(s.materials.size(), 1u);
    const Material& m = s.materials[0];
    EXPECT_FLOAT_EQ(m.roughnessFactor, 0.0f);  // glossiness 1
    EXPECT_NEAR(m.metallicFactor, 0.167f, 0.002f);  // diffuse 1, specular 0.2: Khronos' solveMetallic
    EXPECT_GE(m.baseColorTexture, 0);             // the diffuse texture
    EXPECT_EQ(m.metallicRoughnessTexture, -1);

    // A specular-glossiness texture becomes a roughness texture: G = 1 − glossiness · A.
    TempDir dir;
    json doc = quadJson();
    doc["materials"][1]["extensions"]["KHR_materials_pbrSpecularGlossiness"] = {
        {"diffuseFactor", {0.5, 0.5, 0.5, 1.0}}, {"specularFactor", {0.04, 0.04, 0.04}}, {"glossinessFactor", 0.5},
        {"specularGlossinessTexture", {{"index", 0}}}};
    const Scene q = loadGltf(writeGltf(dir, doc));
    const Material& painted = q.materials[1];
    EXPECT_FLOAT_EQ(painted.metallicFactor, 0.0f);  // dielectric specular
    EXPECT_FLOAT_EQ(painted.roughnessFactor, 1.0f);
    ASSERT_GE(painted.metallicRoughnessTexture, 0);
    const TextureImage& rough = q.textures[size_t(painted.metallicRoughnessTexture)];
    EXPECT_FALSE(rough.srgb);
    EXPECT_EQ(rough.rgba8[1], uint8_t(std::lround(255.0f * (1.0f - 0.5f * 1.0f))));  // opaque texel: A = 255
    doc["materials"][1]["extensions"]["KHR_materials_pbrSpecularGlossiness"]["specularFactor"] = {1, 2};
    expectError([&] { loadGltf(writeGltf(dir, doc, "bad.gltf")); }, {"material 'Painted' KHR_materials_pbrSpecularGlossiness: specularFactor: expected 3 numbers"});
}

// KHR_texture_transform: uv' = T·R·S·(uv, 1) stored as two rows; identity without the extension.
TEST(Gltf, TextureTransformBecomesTheMaterialsUvRows) {
    TempDir dir;
    json doc = quadJson();
    doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"] = {
        {"offset", {0.5, 0.25}}, {"rotation", 1.5707963267948966}, {"scale", {2.0, 3.0}}};
    const Scene s = loadGltf(writeGltf(dir, doc));
    expectVec(s.materials[0].uvRow0, {1, 0, 0}, 0.0f);  // untouched material: exact identity
    expectVec(s.materials[0].uvRow1, {0, 1, 0}, 0.0f);
    expectVec(s.materials[1].uvRow0, {0, 3, 0.5f}, 1e-6f);   // (cos·sx, sin·sy, offset.x)
    expectVec(s.materials[1].uvRow1, {-2, 0, 0.25f}, 1e-6f);  // (−sin·sx, cos·sy, offset.y)
    doc["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["scale"] = {1};
    expectError([&] { loadGltf(writeGltf(dir, doc, "bad.gltf")); },
                {"material 'Painted' baseColorTexture KHR_texture_transform: scale: expected 2 numbers"});
}

TEST(Gltf, AlphaMaskAndCutoff) {
    TempDir dir;
    json doc = quadJson();
    doc["materials"][1]["alphaMode"] = "MASK";
    doc["materials"][1]["alphaCutoff"] = 0.3;
    const Scene s = loadGltf(writeGltf(dir, doc));
    EXPECT_FALSE(s.materials[0].masked);
    EXPECT_TRUE(s.materials[1].masked);
    EXPECT_FLOAT_EQ(s.materials[1].alphaCutoff, 0.3f);
    EXPECT_FALSE(s.materials[1].transparent);
    doc["materials"][1]["alphaCutoff"] = -1.0;
    expectError([&] { loadGltf(writeGltf(dir, doc, "bad.gltf")); }, {"material 'Painted'", "alphaCutoff"});
}

// Appends `bytes` to the embedded buffer behind a new bufferView and accessor; returns the accessor.
int appendAccessor(json& doc, const std::vector<uint8_t>& data, json accessor) {
    std::string uri = doc["buffers"][0]["uri"];
    const std::string prefix = uri.substr(0, uri.find(',') + 1);
    std::vector<uint8_t> bytes = unbase64(uri.substr(prefix.size()));
    bytes.resize((bytes.size() + 3) & ~size_t(3));  // 4-byte aligned
    const size_t at = bytes.size();
    bytes.insert(bytes.end(), data.begin(), data.end());
    doc["buffers"][0]["uri"] = prefix + base64(bytes);
    doc["buffers"][0]["byteLength"] = bytes.size();
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", data.size()}});
    accessor["bufferView"] = doc["bufferViews"].size() - 1;
    doc["accessors"].push_back(accessor);
    return int(doc["accessors"].size() - 1);
}

// COLOR_0 (VEC4 normalized bytes, VEC3 floats) as 16-bit unorm per vertex; meshes without it white.
TEST(Gltf, VertexColoursMultiplyTheBaseColour) {
    TempDir dir;
    json doc = quadJson();
    const std::vector<uint8_t> bytes = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0, 51, 102, 153, 204};
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        appendAccessor(doc, bytes, {{"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC4"}});
    const Scene s = loadGltf(writeGltf(dir, doc));
    const Mesh& quad = s.meshes[s.draws[0].mesh];
    ASSERT_TRUE(quad.vertexColors);
    const Vertex* v = &s.vertices[size_t(quad.vertexOffset)];
    EXPECT_EQ(v[0].color, glm::u16vec4(65535, 0, 0, 65535));
    EXPECT_EQ(v[1].color, glm::u16vec4(0, 65535, 0, 32896));  // 128 / 255
    EXPECT_EQ(v[3].color, glm::u16vec4(13107, 26214, 39321, 52428));
    const Mesh& plain = s.meshes[drawOf(s, "Plain").mesh];
    EXPECT_FALSE(plain.vertexColors);
    EXPECT_EQ(s.vertices[size_t(plain.vertexOffset)].color, glm::u16vec4(65535));

    json floats = quadJson();
    std::vector<uint8_t> raw(4 * 12);
    const float rgb[12] = {0.5f, 0.25f, 2.0f, 0, 0, 0, 1, 1, 1, 0.1f, 0.2f, 0.3f};
    std::memcpy(raw.data(), rgb, sizeof rgb);
    const int accessor = appendAccessor(floats, raw, {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    floats["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = accessor;
    const Scene f = loadGltf(writeGltf(dir, floats, "floats.gltf"));
    const Vertex& first = f.vertices[size_t(f.meshes[f.draws[0].mesh].vertexOffset)];
    EXPECT_EQ(first.color, glm::u16vec4(32768, 16384, 65535, 65535));  // clamped to 1; VEC3 is opaque

    floats["accessors"][size_t(accessor)]["type"] = "SCALAR";
    floats["accessors"][size_t(accessor)]["count"] = 4;
    expectError([&] { loadGltf(writeGltf(dir, floats, "bad.gltf")); }, {"mesh 'ReflectiveQuad' primitive 0: COLOR_0", "VEC3/VEC4"});
}

// emissiveFactor × KHR_materials_emissive_strength, the emissive texture sRGB, bad values refused.
TEST(Gltf, EmissiveFactorStrengthAndTexture) {
    TempDir dir;
    json doc = quadJson();
    doc["materials"][1]["emissiveFactor"] = {1.0, 0.5, 0.0};
    doc["materials"][1]["emissiveTexture"] = {{"index", 0}};
    doc["materials"][1]["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", 4.0}};
    doc["materials"][0]["emissiveTexture"] = {{"index", 0}};  // under the default factor 0: emits nothing
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    const Scene s = loadGltf(writeGltf(dir, doc));
    expectVec(s.materials[1].emissiveFactor, {4, 2, 0}, 0.0f);
    ASSERT_GE(s.materials[1].emissiveTexture, 0);
    EXPECT_TRUE(s.textures[size_t(s.materials[1].emissiveTexture)].srgb);
    expectVec(s.materials[0].emissiveFactor, {0, 0, 0}, 0.0f);
    EXPECT_EQ(s.materials[0].emissiveTexture, -1);

    doc["materials"][1]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = -2.0;
    expectError([&] { loadGltf(writeGltf(dir, doc, "bad.gltf")); },
                {"material 'Painted' KHR_materials_emissive_strength: emissiveStrength: expected a finite number >= 0"});
    doc["materials"][1]["extensions"].erase("KHR_materials_emissive_strength");
    doc["materials"][1]["emissiveFactor"] = {1.0, -0.5, 0.0};
    expectError([&] { loadGltf(writeGltf(dir, doc, "bad2.gltf")); }, {"material 'Painted': emissiveFactor: expected finite numbers >= 0"});
}

// Required extensions the loader implements load; an unknown optional one is named on one line.
TEST(Gltf, SupportedExtensionsMayBeRequiredUnknownOptionalOnesWarn) {
    TempDir dir;
    json doc = quadJson();
    doc["extensionsUsed"] = {"KHR_texture_transform", "EXT_not_a_real_extension"};
    doc["extensionsRequired"] = {"KHR_texture_transform"};
    const std::string path = writeGltf(dir, doc);
    testing::internal::CaptureStderr();
    const Scene s = loadGltf(path);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(s.draws.size(), 4u);
    EXPECT_EQ(err, path + ": extensionsUsed: 'EXT_not_a_real_extension' is not supported; ignored\n");
}

TEST(Gltf, PointsAndLinesAreSkipped) {
    TempDir dir;
    json doc = quadJson();
    doc["meshes"][1]["primitives"][0]["mode"] = 1;  // LINES
    const Scene s = loadGltf(writeGltf(dir, doc));
    EXPECT_EQ(s.draws.size(), 3u);
    EXPECT_EQ(s.meshes.size(), 1u);
}

TEST(Gltf, StripsBecomeLists) {
    TempDir dir;
    json doc = quadJson();
    doc["meshes"][1]["primitives"][0]["mode"] = 5;  // TRIANGLE_STRIP over 6 indices → 4 triangles
    const Scene s = loadGltf(writeGltf(dir, doc));
    EXPECT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.meshes[1].indexCount, 12u);
}

TEST(Gltf, NoScenesUsesRootNodes) {
    TempDir dir;
    json doc = quadJson();
    doc.erase("scene");
    doc.erase("scenes");
    const Scene s = loadGltf(writeGltf(dir, doc));
    EXPECT_EQ(s.draws.size(), 4u);  // Ramp is reached once, through Scaler
    EXPECT_EQ(s.cameras.size(), 1u);
}

TEST(Gltf, NodeMatrixTransform) {
    TempDir dir;
    json doc = quadJson();
    // Column-major translate(0, 3, 0) · scale(2) instead of TRS.
    doc["nodes"][4].erase("translation");
    doc["nodes"][4]["matrix"] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 3, 0, 1};
    const Scene s = loadGltf(writeGltf(dir, doc));
    const DrawItem& plain = drawOf(s, "Plain");
    EXPECT_EQ(glm::vec3(plain.world[3]), glm::vec3(0, 3, 0));
    EXPECT_EQ(plain.world[0][0], 2.0f);
    EXPECT_NEAR(s.boundsMax.x, 2.0f, 1e-6f);
}
