// Reflector file parsing and validation: the good file, and every bad-input rule of the contract.
#include "scene/reflector.hpp"

#include "test_util.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

using namespace ppr::scene;
using ppr::scene::test::dataPath;
using ppr::scene::test::expectError;

TEST(Reflector, LoadsGoodFile) {
    const auto rs = loadReflectorFile(dataPath("reflectors/good.json"));
    ASSERT_EQ(rs.size(), 3u);
    EXPECT_EQ(rs[0].name, "floor");
    EXPECT_EQ(rs[0].normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(rs[0].halfExtents, glm::vec2(5, 5));
    EXPECT_EQ(rs[1].kind, ReflectorKind::Glass);
    EXPECT_FLOAT_EQ(rs[1].reflectance, 0.25f);
    EXPECT_EQ(rs[1].center, glm::vec3(0, 1.5f, -4));
    // kind and reflectance are optional.
    EXPECT_EQ(rs[2].kind, ReflectorKind::Opaque);
    EXPECT_EQ(rs[2].reflectance, 1.0f);
}

TEST(Reflector, EmptyListIsValid) {
    EXPECT_TRUE(parseReflectorFile(R"({"version":1,"reflectors":[]})", "empty.json").empty());
}

struct BadCase {
    const char* file;
    std::vector<std::string> expected;  // substrings of the one-line message, besides the file name
};

class BadReflectorFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadReflectorFile, FailsWithFileFieldAndProblem) {
    const BadCase& c = GetParam();
    const std::string path = dataPath(std::string("reflectors/") + c.file);
    std::vector<std::string> parts = c.expected;
    parts.push_back(c.file);
    const std::string msg = expectError([&] { loadReflectorFile(path); }, parts);
    EXPECT_EQ(msg.rfind(path, 0), 0u) << "message must start with the file: " << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadReflectorFile,
    ::testing::Values(
        BadCase{"bad_nan.json", {"JSON parse error at byte"}},
        BadCase{"bad_infinity.json", {"JSON error", "1e999"}},
        BadCase{"bad_broken.json", {"JSON parse error at byte"}},
        BadCase{"bad_null_number.json", {"reflectors[0].center[1]", "expected a finite number, got null"}},
        BadCase{"bad_zero_extents.json", {"reflectors[0].half_extents: must be > 0.0001 m"}},
        BadCase{"bad_zero_normal.json", {"reflectors[0].normal: zero length"}},
        BadCase{"bad_nonunit_normal.json", {"reflectors[0].normal: not unit length (|n| = 1.2)"}},
        BadCase{"bad_nonunit_tangent.json", {"reflectors[0].tangent: not unit length (|t| = 0.5)"}},
        BadCase{"bad_tangent_parallel.json", {"reflectors[0].tangent: parallel to normal"}},
        BadCase{"bad_tangent_not_orthogonal.json", {"reflectors[0].tangent: not orthogonal to normal (dot = 0.0995"}},
        BadCase{"bad_version.json", {"version: expected 1, got 2"}},
        BadCase{"bad_version_missing.json", {"version: missing"}},
        BadCase{"bad_unknown_field.json",
                {"reflectors[1].colour: unknown field (known: name, center, normal, tangent, half_extents, kind, reflectance)"}},
        BadCase{"bad_unknown_top_level.json", {"extra: unknown field (known: version, reflectors)"}},
        BadCase{"bad_missing_name.json", {"reflectors[0].name: missing required field"}},
        BadCase{"bad_missing_half_extents.json", {"reflectors[0].half_extents: missing required field"}},
        BadCase{"bad_empty_name.json", {"reflectors[0].name: expected a non-empty string"}},
        BadCase{"bad_duplicate_names.json", {"reflectors[1].name: duplicate name 'floor'"}},
        BadCase{"bad_kind.json", {"reflectors[0].kind", "metal"}},
        BadCase{"bad_reflectance.json", {"reflectors[0].reflectance: must be within 0..1, got 1.5"}},
        BadCase{"bad_center_count.json", {"reflectors[0].center: expected an array of 3 numbers"}},
        BadCase{"bad_center_string.json", {"reflectors[0].center[1]", "expected a finite number"}},
        BadCase{"bad_reflectors_not_array.json", {"reflectors: expected an array"}},
        BadCase{"bad_not_object.json", {"expected a JSON object"}},
        BadCase{"bad_huge_extents.json", {"reflectors[0].half_extents: must be at most 100000 m, got [1e+09, 1e+09]"}},
        BadCase{"bad_far_center.json", {"reflectors[0].center: beyond 1e+06 m of the origin"}}),
    [](const auto& info) {
        std::string name = info.param.file;
        name = name.substr(0, name.find('.'));
        for (char& ch : name)
            if (!isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

TEST(Reflector, TooManyEntriesAreRefusedBeforeParsingThem) {
    std::string text = R"({"version":1,"reflectors":[)";
    for (size_t i = 0; i <= kMaxReflectors; ++i) text += (i ? ",{}" : "{}");
    text += "]}";
    expectError([&] { parseReflectorFile(text, "many.json"); }, {"many.json: reflectors: 16385 entries, at most 16384"});
}

TEST(Reflector, MissingFileNamesIt) {
    expectError([] { loadReflectorFile("/nonexistent/dir/scene.reflectors.json"); },
                {"/nonexistent/dir/scene.reflectors.json", "no such file"});
}

TEST(Reflector, InMemoryNonFiniteIsRejected) {
    // nlohmann can hold NaN/inf when JSON is built in code (e.g. by the editor); parsing must catch it.
    nlohmann::json j = {{"name", "a"}, {"center", {0.0, std::nan(""), 0.0}}, {"normal", {0, 1, 0}},
                        {"tangent", {1, 0, 0}}, {"half_extents", {1, 1}}};
    expectError([&] { parseReflector(j, "mem.json: reflectors[0]"); }, {"mem.json: reflectors[0].center[1]", "not a finite number"});
    j["center"] = {0, 0, 0};
    j["half_extents"] = {1.0, std::numeric_limits<double>::infinity()};
    expectError([&] { parseReflector(j, "mem.json: reflectors[0]"); }, {"mem.json: reflectors[0].half_extents[1]", "not a finite"});
}

TEST(Reflector, ValidateReflector) {
    Reflector r;
    r.name = "ok";
    EXPECT_EQ(validateReflector(r), "");
    Reflector bad = r;
    bad.halfExtents = {0.00005f, 1.0f};
    EXPECT_EQ(validateReflector(bad).rfind("half_extents: must be > 0.0001 m", 0), 0u);
    bad = r;
    bad.normal = {0, 0, 0};
    EXPECT_EQ(validateReflector(bad), "normal: zero length");
    bad = r;
    bad.tangent = glm::normalize(glm::vec3(1, 0.01f, 0));
    EXPECT_EQ(validateReflector(bad).rfind("tangent: not orthogonal to normal (dot = ", 0), 0u);
    bad = r;
    bad.reflectance = -0.1f;
    EXPECT_EQ(validateReflector(bad).rfind("reflectance:", 0), 0u);
    bad = r;
    bad.name.clear();
    EXPECT_EQ(validateReflector(bad).rfind("name:", 0), 0u);
}

TEST(Reflector, ToleranceAllowsSmallErrors) {
    // Authoring tools write 6-7 significant digits; that must not trip the unit/orthogonality checks.
    const auto rs = parseReflectorFile(
        R"({"version":1,"reflectors":[{"name":"tilted","center":[0,0,0],"normal":[0.7071068,0.7071068,0],
            "tangent":[0.7071067,-0.7071069,0],"half_extents":[1,1]}]})",
        "tilted.json");
    ASSERT_EQ(rs.size(), 1u);
}

TEST(Reflector, ContainsProjected) {
    Reflector r;
    r.center = {1, 0, 0};
    r.normal = {0, 1, 0};
    r.tangent = {1, 0, 0};  // bitangent = cross(n, t) = -Z
    r.halfExtents = {2, 1};
    EXPECT_TRUE(r.containsProjected({2.9f, 0, 0.9f}));
    EXPECT_FALSE(r.containsProjected({3.1f, 0, 0}));
    EXPECT_FALSE(r.containsProjected({1, 0, 1.1f}));
    EXPECT_TRUE(r.containsProjected({1, 0, 1.1f}, 0.2f));
    EXPECT_EQ(r.bitangent(), glm::vec3(0, 0, -1));
    EXPECT_FLOAT_EQ(r.planeDistance({5, 2, 7}), 2.0f);
}
