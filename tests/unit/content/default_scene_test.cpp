// Checks the default-scene generator's output: reproducible bytes, the cameras and reflectors the
// renderer and tests rely on, agreement between node extras and the sidecar reflector file, and
// reflective geometry lying inside its reflector rectangle. Runs the generator twice into temp dirs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct V3 {
    double x = 0, y = 0, z = 0;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(V3 a) { return std::sqrt(dot(a, a)); }
V3 v3(const json& j) { return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()}; }

// Rotates v by unit quaternion q = (x, y, z, w).
V3 rotate(const std::array<double, 4>& q, V3 v) {
    const V3 u{q[0], q[1], q[2]};
    const double w = q[3];
    return u * (2.0 * dot(u, v)) + v * (w * w - dot(u, u)) + cross(u, v) * (2.0 * w);
}

std::string readFile(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

struct Reflector {
    std::string name;
    V3 center, normal, tangent;
    double halfU = 0, halfV = 0, reflectance = 0;
    std::string kind;
};
Reflector parseReflector(const json& j) {
    Reflector r;
    r.name = j.at("name").get<std::string>();
    r.center = v3(j.at("center"));
    r.normal = v3(j.at("normal"));
    r.tangent = v3(j.at("tangent"));
    r.halfU = j.at("half_extents").at(0).get<double>();
    r.halfV = j.at("half_extents").at(1).get<double>();
    r.kind = j.at("kind").get<std::string>();
    r.reflectance = j.at("reflectance").get<double>();
    return r;
}

class DefaultScene : public ::testing::Test {
protected:
    static inline fs::path dirA, dirB;
    static inline json gltf;
    static inline std::string bin;
    static inline bool generated = false;

    static void SetUpTestSuite() {
        const fs::path root = fs::temp_directory_path() / ("ppr_unit_content_" + std::to_string(::getpid()));
        fs::remove_all(root);
        dirA = root / "a";
        dirB = root / "b";
        const std::string exe = std::string(PPR_BINARY_DIR) + "/content/ppr_make_default_scene";
        const int rcA = std::system(("'" + exe + "' '" + dirA.string() + "'").c_str());
        const int rcB = std::system(("'" + exe + "' '" + dirB.string() + "'").c_str());
        generated = rcA == 0 && rcB == 0 && fs::exists(dirA / "default.gltf");
        if (!generated) return;
        gltf = json::parse(readFile(dirA / "default.gltf"));
        bin = readFile(dirA / "default.bin");
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(dirA.parent_path(), ec);
    }
    void SetUp() override { ASSERT_TRUE(generated) << "generator failed to run: " << PPR_BINARY_DIR "/content/ppr_make_default_scene"; }

    // The float data of an accessor (POSITION etc.), as doubles, `components` per element.
    static std::vector<double> floats(int accessor, int components) {
        const json& a = gltf.at("accessors").at(accessor);
        const json& view = gltf.at("bufferViews").at(a.at("bufferView").get<int>());
        const size_t offset = view.value("byteOffset", size_t{0}) + a.value("byteOffset", size_t{0});
        const size_t count = a.at("count").get<size_t>() * static_cast<size_t>(components);
        std::vector<double> out(count);
        for (size_t i = 0; i < count; ++i) {
            float f;
            std::memcpy(&f, bin.data() + offset + i * 4, 4);
            out[i] = f;
        }
        return out;
    }
    static std::vector<V3> positions(int mesh) {
        const int acc = gltf.at("meshes").at(mesh).at("primitives").at(0).at("attributes").at("POSITION").get<int>();
        const std::vector<double> f = floats(acc, 3);
        std::vector<V3> out;
        for (size_t i = 0; i + 2 < f.size(); i += 3) out.push_back({f[i], f[i + 1], f[i + 2]});
        return out;
    }
    static V3 translation(const json& node) { return node.contains("translation") ? v3(node["translation"]) : V3{}; }
    // Node-extras reflectors, moved to world space by the node translation.
    static std::vector<Reflector> extrasReflectors() {
        std::vector<Reflector> out;
        for (const json& n : gltf.at("nodes")) {
            if (!n.contains("extras") || !n["extras"].contains("ppr_reflector")) continue;
            Reflector r = parseReflector(n["extras"]["ppr_reflector"]);
            r.center = r.center + translation(n);
            out.push_back(r);
        }
        return out;
    }
};

TEST_F(DefaultScene, TwoRunsWriteIdenticalBytes) {
    std::vector<std::string> namesA, namesB;
    for (const auto& e : fs::directory_iterator(dirA)) namesA.push_back(e.path().filename().string());
    for (const auto& e : fs::directory_iterator(dirB)) namesB.push_back(e.path().filename().string());
    std::sort(namesA.begin(), namesA.end());
    std::sort(namesB.begin(), namesB.end());
    ASSERT_EQ(namesA, namesB);
    uintmax_t total = 0;
    for (const std::string& name : namesA) {
        EXPECT_EQ(readFile(dirA / name), readFile(dirB / name)) << name << " differs between runs";
        total += fs::file_size(dirA / name);
    }
    EXPECT_LT(total, 3u * 1024u * 1024u) << "default scene should stay small";
}

TEST_F(DefaultScene, AssetBuffersAndImagesAreConsistent) {
    EXPECT_EQ(gltf.at("asset").at("version"), "2.0");
    EXPECT_EQ(gltf.at("asset").at("generator"), "ppr_make_default_scene");
    ASSERT_EQ(gltf.at("buffers").size(), 1u);
    EXPECT_EQ(gltf["buffers"][0].at("byteLength").get<size_t>(), bin.size());
    for (const json& view : gltf.at("bufferViews"))
        EXPECT_LE(view.value("byteOffset", size_t{0}) + view.at("byteLength").get<size_t>(), bin.size());
    for (const json& image : gltf.at("images")) {
        const std::string png = readFile(dirA / image.at("uri").get<std::string>());
        ASSERT_GE(png.size(), 8u) << image["uri"];
        EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << image["uri"];
    }
    for (size_t m = 0; m < gltf.at("meshes").size(); ++m) {
        const json& prim = gltf["meshes"][m].at("primitives").at(0);
        EXPECT_EQ(prim.value("mode", 4), 4);
        const json& attrs = prim.at("attributes");
        for (const char* a : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"}) EXPECT_TRUE(attrs.contains(a)) << a;
        const json& posAcc = gltf["accessors"][attrs["POSITION"].get<int>()];
        const std::vector<V3> pos = positions(static_cast<int>(m));
        // min/max must match the data exactly (loaders use them as bounds).
        V3 lo = pos[0], hi = pos[0];
        for (const V3& p : pos) {
            lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
            hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
        }
        EXPECT_EQ(v3(posAcc.at("min")).x, lo.x);
        EXPECT_EQ(v3(posAcc.at("max")).y, hi.y);
        const json& idxAcc = gltf["accessors"][prim.at("indices").get<int>()];
        EXPECT_EQ(idxAcc.at("componentType"), 5125);
        const json& view = gltf["bufferViews"][idxAcc.at("bufferView").get<int>()];
        const size_t count = idxAcc.at("count").get<size_t>();
        EXPECT_EQ(count % 3, 0u);
        for (size_t i = 0; i < count; ++i) {
            uint32_t index;
            std::memcpy(&index, bin.data() + view.value("byteOffset", size_t{0}) + i * 4, 4);
            ASSERT_LT(index, pos.size()) << "mesh " << m;
        }
        // Unit normals and tangents with w = ±1.
        const std::vector<double> n = floats(attrs["NORMAL"].get<int>(), 3), t = floats(attrs["TANGENT"].get<int>(), 4);
        for (size_t i = 0; i < pos.size(); ++i) {
            ASSERT_NEAR(length({n[3 * i], n[3 * i + 1], n[3 * i + 2]}), 1.0, 1e-4) << "mesh " << m;
            ASSERT_NEAR(length({t[4 * i], t[4 * i + 1], t[4 * i + 2]}), 1.0, 1e-4) << "mesh " << m;
            ASSERT_EQ(std::fabs(t[4 * i + 3]), 1.0) << "mesh " << m;
        }
    }
}

TEST_F(DefaultScene, HasTheNamedCamerasLookingAtReflectors) {
    const std::vector<Reflector> reflectors = extrasReflectors();
    std::map<std::string, std::vector<std::string>> seen;  // camera → reflectors whose centre is in view
    for (const json& n : gltf.at("nodes")) {
        if (!n.contains("camera")) continue;
        const json& cam = gltf.at("cameras").at(n["camera"].get<int>());
        EXPECT_EQ(cam.at("name"), n.at("name"));
        const json& p = cam.at("perspective");
        EXPECT_NEAR(p.at("aspectRatio").get<double>(), 16.0 / 9.0, 1e-5);
        EXPECT_NEAR(p.at("znear").get<double>(), 0.05, 1e-9);
        EXPECT_FALSE(p.contains("zfar"));
        const double yfov = p.at("yfov").get<double>();
        const json& r = n.at("rotation");
        const std::array<double, 4> q{r[0].get<double>(), r[1].get<double>(), r[2].get<double>(), r[3].get<double>()};
        EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-5);
        // Camera roll must be zero: the camera's local +X stays horizontal.
        EXPECT_NEAR(rotate(q, {1, 0, 0}).y, 0.0, 1e-5) << n["name"];
        const std::array<double, 4> inv{-q[0], -q[1], -q[2], q[3]};
        std::vector<std::string>& list = seen[n.at("name").get<std::string>()];
        for (const Reflector& refl : reflectors) {
            const V3 c = rotate(inv, refl.center - translation(n));  // camera space, looking down −Z
            if (c.z >= 0) continue;
            const double ty = std::tan(yfov / 2);
            if (std::fabs(c.x / -c.z) < ty * 16.0 / 9.0 && std::fabs(c.y / -c.z) < ty &&
                dot(refl.normal, translation(n) - refl.center) > 0)  // seen from the reflecting side
                list.push_back(refl.name);
        }
    }
    for (const char* name : {"overview", "puddles", "grazing", "stairs", "mirror"})
        ASSERT_TRUE(seen.count(name)) << "missing camera " << name;
    auto has = [&](const std::string& cam, const std::string& refl) {
        const auto& l = seen[cam];
        return std::find(l.begin(), l.end(), refl) != l.end();
    };
    EXPECT_TRUE(has("puddles", "puddle_pot"));
    EXPECT_TRUE(has("grazing", "puddle_large"));
    EXPECT_TRUE(has("mirror", "mirror"));
    EXPECT_GE(std::count_if(seen["stairs"].begin(), seen["stairs"].end(), [](const std::string& s) { return s.rfind("step_", 0) == 0; }), 5);
    EXPECT_GE(seen["overview"].size(), 8u);
    // The normal-mapped corner: its camera sees all three, and no other camera sees any of them (their
    // pictures stay as they were before the corner existed).
    for (const char* r : {"tiles_polished", "puddle_rippled", "mirror_wavy"}) {
        EXPECT_TRUE(has("normalmap", r)) << r;
        for (const auto& [cam, list] : seen)
            if (cam != "normalmap") EXPECT_FALSE(has(cam, r)) << r << " seen from " << cam;
    }
}

TEST_F(DefaultScene, NormalMappedReflectorsHaveNormalMaps) {
    // Each of the corner's reflectors is drawn with a reflective material that has a normal texture.
    std::map<std::string, int> materialOf;
    for (const json& n : gltf.at("nodes"))
        if (n.contains("mesh")) materialOf[n.at("name")] = gltf["meshes"][n["mesh"].get<int>()]["primitives"][0].value("material", -1);
    for (const char* r : {"tiles_polished", "puddle_rippled", "mirror_wavy"}) {
        ASSERT_TRUE(materialOf.count(r)) << r;
        const json& m = gltf.at("materials").at(materialOf[r]);
        EXPECT_TRUE(m.contains("normalTexture")) << r;
        EXPECT_TRUE(m.at("extras").value("ppr_reflective", false)) << r;
    }
}

TEST_F(DefaultScene, HasTheRequiredReflectorKinds) {
    const std::vector<Reflector> rs = extrasReflectors();
    int puddles = 0, vertical = 0, glass = 0;
    std::set<double> stepHeights;
    for (const Reflector& r : rs) {
        if (r.name.rfind("puddle_", 0) == 0 && r.normal.y > 0.999999 && r.kind == "opaque") ++puddles;
        if (std::fabs(r.normal.y) < 1e-9 && r.kind == "opaque") ++vertical;
        if (r.kind == "glass") ++glass;
        if (r.name.rfind("step_", 0) == 0 && r.normal.y > 0.999999) stepHeights.insert(r.center.y);
    }
    EXPECT_GE(puddles, 4);
    EXPECT_GE(vertical, 1);
    EXPECT_GE(stepHeights.size(), 5u) << "parallel step reflectors at distinct heights";
    EXPECT_GE(glass, 2);
    std::set<std::string> names;
    for (const Reflector& r : rs) EXPECT_TRUE(names.insert(r.name).second) << "duplicate reflector " << r.name;
}

TEST_F(DefaultScene, ReflectorFileMatchesNodeExtras) {
    const json file = json::parse(readFile(dirA / "default.reflectors.json"));
    EXPECT_EQ(file.at("version"), 1);
    const std::vector<Reflector> fromExtras = extrasReflectors();
    const json& list = file.at("reflectors");
    ASSERT_EQ(list.size(), fromExtras.size());
    const std::set<std::string> keys{"name", "center", "normal", "tangent", "half_extents", "kind", "reflectance"};
    for (size_t i = 0; i < list.size(); ++i) {
        std::set<std::string> got;
        for (const auto& [k, v] : list[i].items()) got.insert(k);
        EXPECT_EQ(got, keys);
        const Reflector a = parseReflector(list[i]), &b = fromExtras[i];
        SCOPED_TRACE(a.name);
        EXPECT_EQ(a.name, b.name);
        for (const auto& [x, y] : {std::pair{a.center, b.center}, {a.normal, b.normal}, {a.tangent, b.tangent}})
            EXPECT_LT(length(x - y), 1e-6);
        EXPECT_EQ(a.halfU, b.halfU);
        EXPECT_EQ(a.halfV, b.halfV);
        EXPECT_EQ(a.kind, b.kind);
        EXPECT_EQ(a.reflectance, b.reflectance);
        EXPECT_NEAR(length(a.normal), 1.0, 1e-6);
        EXPECT_NEAR(length(a.tangent), 1.0, 1e-6);
        EXPECT_NEAR(dot(a.normal, a.tangent), 0.0, 1e-6);
        EXPECT_GT(a.halfU, 0.0);
        EXPECT_GT(a.halfV, 0.0);
        EXPECT_TRUE(a.kind == "opaque" || a.kind == "glass");
        EXPECT_GE(a.reflectance, 0.0);
        EXPECT_LE(a.reflectance, 1.0);
    }
}

TEST_F(DefaultScene, ReflectiveGeometryLiesInItsReflector) {
    int checked = 0;
    for (const json& n : gltf.at("nodes")) {
        if (!n.contains("mesh")) continue;
        const int mesh = n["mesh"].get<int>();
        const json& mat = gltf.at("materials").at(gltf["meshes"][mesh]["primitives"][0].at("material").get<int>());
        const bool reflectiveMaterial = mat.contains("extras") && mat["extras"].value("ppr_reflective", false);
        const bool hasReflector = n.contains("extras") && n["extras"].contains("ppr_reflector");
        // Curved reflective surfaces have no rectangle: the screen-space fallback shades them.
        const bool curved = n["name"] == "sphere_chrome" || n["name"] == "post_steel";
        if (curved) {
            EXPECT_TRUE(reflectiveMaterial) << n["name"];
            EXPECT_FALSE(hasReflector) << n["name"];
            continue;
        }
        EXPECT_EQ(reflectiveMaterial, hasReflector) << n["name"] << ": reflective material and reflector go together";
        if (!hasReflector) continue;
        const Reflector r = parseReflector(n["extras"]["ppr_reflector"]);
        EXPECT_EQ(r.name, n.at("name"));
        EXPECT_FALSE(n.contains("rotation") || n.contains("scale") || n.contains("matrix")) << "reflective nodes are translated only";
        const V3 b = cross(r.normal, r.tangent);
        for (const V3& p : positions(mesh)) {
            const V3 d = p - r.center;  // both in node space
            ASSERT_LT(std::fabs(dot(d, r.normal)), 1e-4) << r.name << ": vertex off the reflector plane";
            ASSERT_LE(std::fabs(dot(d, r.tangent)), r.halfU + 1e-4) << r.name << ": vertex outside along tangent";
            ASSERT_LE(std::fabs(dot(d, b)), r.halfV + 1e-4) << r.name << ": vertex outside along bitangent";
        }
        ++checked;
    }
    EXPECT_GE(checked, 13);
}

}  // namespace
