// Reflector serialisation: exact float round trip and the editor's atomic save.
#include "scene/reflector.hpp"

#include "test_util.hpp"

#include <nlohmann/json.hpp>

#include <random>

using namespace ppr::scene;
using ppr::scene::test::expectError;
using ppr::scene::test::readText;
using ppr::scene::test::TempDir;
using ppr::scene::test::writeText;

namespace {

std::vector<Reflector> randomReflectors(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(-1000.0f, 1000.0f), ext(1e-3f, 50.0f), refl(0.0f, 1.0f);
    std::vector<Reflector> out;
    for (int i = 0; i < count; ++i) {
        Reflector r;
        r.name = std::string("r").append(std::to_string(i)).append(i % 3 == 0 ? " with \"quotes\" and ünïcode" : "");
        r.center = {pos(rng), pos(rng) * 1e-6f, pos(rng)};  // tiny and large magnitudes
        glm::vec3 n;
        do n = {u(rng), u(rng), u(rng)};
        while (glm::length(n) < 0.1f);
        r.normal = glm::normalize(n);
        glm::vec3 t = glm::cross(r.normal, glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(2, 0, 0));
        r.tangent = glm::normalize(t - r.normal * glm::dot(r.normal, t));
        r.halfExtents = {ext(rng), ext(rng)};
        r.kind = i % 2 ? ReflectorKind::Glass : ReflectorKind::Opaque;
        r.reflectance = i == 0 ? 1.0f : refl(rng);
        EXPECT_EQ(validateReflector(r), "") << "test generator made an invalid reflector";
        out.push_back(r);
    }
    return out;
}

void expectSame(const std::vector<Reflector>& a, const std::vector<Reflector>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].name, b[i].name);
        // Exact equality on purpose: a save/load cycle in the editor must not drift.
        EXPECT_EQ(a[i].center, b[i].center) << i;
        EXPECT_EQ(a[i].normal, b[i].normal) << i;
        EXPECT_EQ(a[i].tangent, b[i].tangent) << i;
        EXPECT_EQ(a[i].halfExtents, b[i].halfExtents) << i;
        EXPECT_EQ(a[i].kind, b[i].kind) << i;
        EXPECT_EQ(a[i].reflectance, b[i].reflectance) << i;
    }
}

}  // namespace

TEST(ReflectorIo, RoundTripIsExact) {
    const auto rs = randomReflectors(50, 7);
    const std::string text = reflectorsToJson(rs);
    expectSame(rs, parseReflectorFile(text, "roundtrip.json"));
    // Stable: serialising the parsed result again gives the same bytes.
    EXPECT_EQ(reflectorsToJson(parseReflectorFile(text, "roundtrip.json")), text);
}

TEST(ReflectorIo, OutputIsVersionedAndReadable) {
    Reflector r;
    r.name = "floor";
    r.center = {0.1f, 0.0f, -2.5f};
    r.halfExtents = {5.0f, 5.0f};
    const std::string text = reflectorsToJson({r});
    const auto j = nlohmann::json::parse(text);
    EXPECT_EQ(j.at("version"), 1);
    ASSERT_EQ(j.at("reflectors").size(), 1u);
    EXPECT_EQ(j.at("reflectors")[0].at("kind"), "opaque");
    EXPECT_NE(text.find("\"center\": [0.1, 0.0, -2.5]"), std::string::npos) << text;  // shortest exact decimals
    EXPECT_EQ(reflectorToJson(r).at("name"), "floor");
    EXPECT_TRUE(parseReflectorFile(reflectorsToJson({}), "empty.json").empty());
}

TEST(ReflectorIo, AtomicSaveReplacesAndLeavesNoTemp) {
    TempDir dir;
    const std::string path = dir.file("scene.reflectors.json");
    writeText(path, "old content that is not even JSON");
    const auto rs = randomReflectors(4, 11);
    saveReflectorFileAtomic(path, rs);
    EXPECT_EQ(readText(path), reflectorsToJson(rs));
    expectSame(rs, loadReflectorFile(path));
    for (const auto& entry : std::filesystem::directory_iterator(dir.path))
        EXPECT_EQ(entry.path().filename().string(), "scene.reflectors.json") << "leftover " << entry.path();

    // Saving again over the new file works too (the editor saves repeatedly).
    const auto fewer = randomReflectors(1, 12);
    saveReflectorFileAtomic(path, fewer);
    expectSame(fewer, loadReflectorFile(path));
}

TEST(ReflectorIo, InvalidReflectorsAreNotSaved) {
    TempDir dir;
    const std::string path = dir.file("keep.json");
    auto rs = randomReflectors(2, 3);
    saveReflectorFileAtomic(path, rs);
    const std::string before = readText(path);
    rs[1].halfExtents.x = 0.0f;
    expectError([&] { saveReflectorFileAtomic(path, rs); }, {path, "reflectors[1].half_extents: must be > 0.0001 m"});
    rs[1] = rs[0];
    expectError([&] { saveReflectorFileAtomic(path, rs); }, {path, "reflectors[1].name: duplicate name"});
    EXPECT_EQ(readText(path), before) << "a refused save must leave the previous file intact";
}

TEST(ReflectorIo, SaveIntoMissingDirectoryFails) {
    expectError([] { saveReflectorFileAtomic("/nonexistent/dir/x.json", {}); }, {"/nonexistent/dir/x.json", "cannot save"});
}
