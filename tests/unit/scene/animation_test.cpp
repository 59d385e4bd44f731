// glTF node animation: loading (what moves, validation messages) and SceneAnimation::evaluate
// (STEP / LINEAR / CUBICSPLINE, slerp, the looping clock, hierarchies), on tiny glTF files written
// here with a .bin beside them, and on the generated default scene's bobbing ball.
#include "scene/scene.hpp"

#include "test_util.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>

using namespace ppr::scene;
using ppr::scene::test::dataPath;
using ppr::scene::test::expectError;
using ppr::scene::test::TempDir;
using ppr::scene::test::writeText;
using nlohmann::json;

namespace {

// A glTF document under construction: one triangle mesh, float accessors in one external buffer.
struct Doc {
    json gltf = {{"asset", {{"version", "2.0"}}}, {"nodes", json::array()}, {"accessors", json::array()},
                 {"bufferViews", json::array()}, {"animations", json::array()}};
    std::vector<float> bin;

    Doc() {
        const int pos = accessor({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
        gltf["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", pos}}}}})}}});
    }
    int accessor(const std::vector<float>& data, const std::string& type) {
        const size_t components = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
        gltf["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size() * 4}, {"byteLength", data.size() * 4}});
        gltf["accessors"].push_back(
            {{"bufferView", gltf["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", data.size() / components}, {"type", type}});
        bin.insert(bin.end(), data.begin(), data.end());
        return int(gltf["accessors"].size() - 1);
    }
    int node(json n) {
        gltf["nodes"].push_back(std::move(n));
        return int(gltf["nodes"].size() - 1);
    }
    // One animation named `name` with one channel.
    void animate(int node, const std::string& path, const std::string& interpolation, const std::vector<float>& times,
                 const std::vector<float>& values, const std::string& name = "bob") {
        const int in = accessor(times, "SCALAR"), out = accessor(values, path == "rotation" ? "VEC4" : "VEC3");
        json a = {{"channels", json::array({{{"sampler", 0}, {"target", {{"node", node}, {"path", path}}}}})},
                  {"samplers", json::array({{{"input", in}, {"interpolation", interpolation}, {"output", out}}})}};
        if (!name.empty()) a["name"] = name;
        gltf["animations"].push_back(a);
    }
    std::string write(const TempDir& dir) const {
        json doc = gltf;
        doc["buffers"] = json::array({{{"uri", "anim.bin"}, {"byteLength", bin.size() * 4}}});
        std::string bytes(bin.size() * 4, '\0');
        std::memcpy(bytes.data(), bin.data(), bytes.size());
        writeText(dir.file("anim.bin"), bytes);
        writeText(dir.file("anim.gltf"), doc.dump(1));
        return dir.file("anim.gltf");
    }
    Scene load() const {
        TempDir dir;
        return loadGltf(write(dir));
    }
};

glm::vec3 position(const glm::mat4& m) { return glm::vec3(m[3]); }

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// The single moving draw's position at `seconds`.
glm::vec3 at(const Scene& s, double seconds) {
    std::vector<glm::mat4> worlds;
    s.animation.evaluate(seconds, worlds);
    EXPECT_EQ(worlds.size(), 1u);
    return worlds.empty() ? glm::vec3(NAN) : position(worlds[0]);
}

}  // namespace

TEST(Animation, SceneWithoutAnimationsIsEmpty) {
    Doc d;
    d.node({{"mesh", 0}});
    const Scene s = d.load();
    EXPECT_TRUE(s.animation.empty());
    EXPECT_TRUE(s.animation.channels.empty() && s.animation.nodes.empty());
    std::vector<glm::mat4> worlds(3);
    s.animation.evaluate(1.0, worlds);
    EXPECT_TRUE(worlds.empty());
    EXPECT_TRUE(loadGltf(dataPath("gltf/quad_scene.gltf")).animation.empty());
}

TEST(Animation, StepHoldsThePreviousKey) {
    Doc d;
    d.animate(d.node({{"mesh", 0}, {"translation", {9, 9, 9}}}), "translation", "STEP", {0, 1, 2}, {0, 0, 0, 1, 0, 0, 2, 5, 0});
    const Scene s = d.load();
    ASSERT_EQ(s.animation.draws, std::vector<uint32_t>{0});
    EXPECT_FLOAT_EQ(s.animation.duration, 2.0f);
    expectNear(at(s, 0.0), {0, 0, 0});
    expectNear(at(s, 0.99), {0, 0, 0});
    expectNear(at(s, 1.0), {1, 0, 0});
    expectNear(at(s, 1.99), {1, 0, 0});
    expectNear(position(s.draws[0].world), {9, 9, 9});  // the draw keeps its rest pose
}

TEST(Animation, LinearLerpsTranslationAndScaleAndClampsOutsideTheKeys) {
    Doc d;
    const int n = d.node({{"mesh", 0}});
    d.animate(n, "translation", "LINEAR", {1, 3}, {0, 0, 0, 2, 4, 6});
    d.animate(n, "scale", "LINEAR", {0, 1}, {1, 1, 1, 3, 3, 3}, "");
    const Scene s = d.load();
    EXPECT_FLOAT_EQ(s.animation.duration, 3.0f);  // the longest channel
    std::vector<glm::mat4> w;
    s.animation.evaluate(0.5, w);  // translation before its first key, scale between keys
    expectNear(position(w[0]), {0, 0, 0});
    EXPECT_NEAR(glm::length(glm::vec3(w[0][0])), 2.0f, 1e-5f);
    s.animation.evaluate(2.0, w);  // translation halfway, scale after its last key
    expectNear(position(w[0]), {1, 2, 3});
    EXPECT_NEAR(glm::length(glm::vec3(w[0][1])), 3.0f, 1e-5f);
    s.animation.evaluate(1.0, w);  // exactly at keys
    expectNear(position(w[0]), {0, 0, 0});
    EXPECT_NEAR(glm::length(glm::vec3(w[0][2])), 3.0f, 1e-5f);
}

TEST(Animation, CubicSplineIsHermiteWithTangentsScaledByTheKeyInterval) {
    Doc d;
    // Per key: in-tangent, value, out-tangent (x only).
    d.animate(d.node({{"mesh", 0}}), "translation", "CUBICSPLINE", {0, 2, 4},
              {0, 0, 0, 0, 0, 0, 3, 0, 0, /**/ -1, 0, 0, 1, 0, 0, 0, 0, 0, /**/ 0, 0, 0, 7, 0, 0, 0, 0, 0});
    const Scene s = d.load();
    EXPECT_NEAR(at(s, 0.0).x, 0.0f, 1e-6f);
    EXPECT_NEAR(at(s, 2.0).x, 1.0f, 1e-6f);
    // u = 0.5, interval 2: h00 v0 + 2 h10 b0 + h01 v1 + 2 h11 a1 = 0 + 2·0.125·3 + 0.5·1 + 2·(−0.125)·(−1).
    EXPECT_NEAR(at(s, 1.0).x, 0.75f + 0.5f + 0.25f, 1e-5f);
    // u = 0.25: h00 = 0.84375, h10 = 0.140625, h01 = 0.15625, h11 = −0.046875.
    EXPECT_NEAR(at(s, 0.5).x, 2 * 0.140625f * 3 + 0.15625f + 2 * 0.046875f, 1e-5f);
}

TEST(Animation, RotationSlerpsTheShortWayAndStaysUnit) {
    Doc d;
    const float s45 = std::sqrt(0.5f);
    // Keys of twice unit length; the second is −(90° about +Y): the short way is +45° at the middle.
    d.animate(d.node({{"mesh", 0}}), "rotation", "LINEAR", {0, 1, 2}, {0, 0, 0, 2, 0, -2 * s45, 0, -2 * s45, 0, 0, 0, 2});
    const Scene s = d.load();
    std::vector<glm::mat4> w;
    s.animation.evaluate(0.5, w);
    const glm::mat4 expected = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 1, 0));
    for (int c = 0; c < 3; ++c) {
        expectNear(glm::vec3(w[0][c]), glm::vec3(expected[c]));
        EXPECT_NEAR(glm::length(glm::vec3(w[0][c])), 1.0f, 1e-6f);
    }
    s.animation.evaluate(1.0, w);
    expectNear(glm::vec3(w[0][0]), {0, 0, -1});  // +90° about Y takes +X to −Z
}

TEST(Animation, ClockLoopsOverTheLongestChannel) {
    Doc d;
    d.animate(d.node({{"mesh", 0}}), "translation", "LINEAR", {0, 2}, {0, 0, 0, 2, 0, 0});
    const Scene s = d.load();
    expectNear(at(s, 2.5), {0.5f, 0, 0});
    expectNear(at(s, 2.0), {0, 0, 0});
    expectNear(at(s, 41.0), {1, 0, 0});
    expectNear(at(s, -0.5), {1.5f, 0, 0});
    expectNear(at(s, std::numeric_limits<double>::infinity()), {0, 0, 0});

    Doc one;  // a single key at 0: duration 0, always that key
    one.animate(one.node({{"mesh", 0}}), "translation", "LINEAR", {0}, {4, 5, 6});
    const Scene still = one.load();
    EXPECT_EQ(still.animation.duration, 0.0f);
    expectNear(at(still, 3.7), {4, 5, 6});
}

TEST(Animation, AnimatedParentMovesStillChildren) {
    Doc d;
    const int child = d.node({{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1}}});  // at x + 1
    const int parent = d.node({{"name", "arm"}, {"translation", {0, 1, 0}}, {"children", {child}}});
    d.node({{"name", "base"}, {"translation", {0, 0, 5}}, {"scale", {2, 2, 2}}, {"children", {parent}}});
    d.node({{"mesh", 0}, {"translation", {7, 0, 0}}});  // a still root: not in the animation
    const int empty = d.node({{"name", "bare"}});       // animated, nothing drawn below: dropped
    d.animate(parent, "translation", "LINEAR", {0, 1}, {0, 1, 0, 0, 3, 0});
    d.animate(empty, "translation", "LINEAR", {0, 5}, {0, 0, 0, 1, 1, 1}, "");
    const Scene s = d.load();
    ASSERT_EQ(s.draws.size(), 2u);
    const SceneAnimation& a = s.animation;
    ASSERT_EQ(a.nodes.size(), 2u);  // arm, then its child
    EXPECT_EQ(a.nodes[0].name, "arm");
    EXPECT_EQ(a.nodes[0].parent, -1);
    expectNear(position(a.nodes[0].staticParent), {0, 0, 5});
    EXPECT_EQ(a.nodes[1].parent, 0);
    EXPECT_TRUE(a.nodes[1].matrix.has_value());
    ASSERT_EQ(a.channels.size(), 1u);
    EXPECT_FLOAT_EQ(a.duration, 1.0f);
    ASSERT_EQ(a.drawNode.size(), 1u);
    EXPECT_EQ(a.drawNode[0], 1u);
    const uint32_t moving = a.draws[0];
    EXPECT_EQ(s.draws[moving].world[3].x, 2.0f);  // the child's draw, found by its position
    std::vector<glm::mat4> w;
    a.evaluate(0.0, w);
    for (int c = 0; c < 4; ++c) expectNear(glm::vec3(w[0][c]), glm::vec3(s.draws[moving].world[c]), 1e-6f);
    a.evaluate(0.5, w);
    expectNear(position(w[0]), glm::vec3(0, 0, 5) + 2.0f * glm::vec3(1, 2, 0));  // base scale 2 applies to arm + child
}

TEST(Animation, FuzzSeedMovesAThreeLevelHierarchy) {
    // arm (translation, LINEAR) > hand (rotation, CUBICSPLINE) > finger (scale, STEP); a root "still"
    // turned by normalized SHORT quaternions.
    const Scene s = loadGltf(dataPath("fuzz/gltf/animated_hierarchy.gltf"));
    const SceneAnimation& a = s.animation;
    ASSERT_EQ(a.draws, (std::vector<uint32_t>{0, 1, 2}));
    ASSERT_EQ(a.nodes.size(), 4u);
    EXPECT_EQ(a.nodes[2].parent, 1);
    std::vector<glm::mat4> w;
    a.evaluate(0.5, w);
    // The hand's spline halfway from identity to 90° about +Y, out-tangent (0, 1, 0, 0) at the first
    // key: 0.5 q0 + 0.125 b0 + 0.5 q1, normalised.
    const float s45 = std::sqrt(0.5f);
    const glm::quat q = glm::normalize(glm::quat(0.5f + 0.5f * s45, 0.0f, 0.125f + 0.5f * s45, 0.0f));
    const glm::mat4 hand = glm::translate(glm::mat4(1.0f), {0, 1, 0}) * glm::mat4_cast(q);
    for (int c = 0; c < 4; ++c) {
        expectNear(glm::vec3(w[0][c]), glm::vec3(hand[c]));
        expectNear(glm::vec3(w[1][c]), glm::vec3(hand[c]) * (c < 3 ? 2.0f : 1.0f));
    }
    expectNear(glm::vec3(w[2][0]), {0, 0, -1}, 1e-4f);  // 23170/32767 per component: 90° about +Y
    expectNear(position(w[2]), {3, 0, 0});
}

TEST(Animation, DefaultSceneBobsOnlyTheRedBall) {
    const Scene s = loadGltf(PPR_DEFAULT_SCENE_FILE);
    const SceneAnimation& a = s.animation;
    ASSERT_EQ(a.draws.size(), 1u);
    const DrawItem& ball = s.draws[a.draws[0]];
    EXPECT_EQ(ball.nodeName, "ball_red");
    EXPECT_FLOAT_EQ(a.duration, 2.0f);
    std::vector<glm::mat4> w;
    a.evaluate(0.0, w);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(w[0][c][r], ball.world[c][r], 1e-6f) << c << "," << r;
    a.evaluate(1.0, w);
    expectNear(position(w[0]), position(ball.world) + glm::vec3(0, 0.5f, 0), 1e-6f);
    a.evaluate(2.0, w);
    expectNear(position(w[0]), position(ball.world), 1e-6f);
}

TEST(Animation, UnsupportedTargetsAreIgnored) {
    // Morph-target weights: one warning line, nothing moves.
    std::ostringstream err;
    std::streambuf* old = std::cerr.rdbuf(err.rdbuf());
    Scene s;
    try {
        s = loadGltf("/usr/share/assimp/models/glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf");
    } catch (...) {
        std::cerr.rdbuf(old);
        throw;
    }
    std::cerr.rdbuf(old);
    EXPECT_TRUE(s.animation.empty());
    const std::string text = err.str();
    EXPECT_NE(text.find("'weights' (morph targets) is not supported"), std::string::npos) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    // A skin's joint with nothing drawn below it: its channel is dropped.
    EXPECT_TRUE(loadGltf("/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf").animation.empty());
}

struct BadAnimation {
    const char* name;
    void (*edit)(Doc&);
    std::vector<std::string> expected;
};

class MalformedAnimation : public ::testing::TestWithParam<BadAnimation> {};

TEST_P(MalformedAnimation, RejectedWithOneLineNamingFileChannelAndField) {
    Doc d;
    d.node({{"mesh", 0}});
    GetParam().edit(d);
    TempDir dir;
    const std::string path = d.write(dir);
    std::vector<std::string> parts = GetParam().expected;
    parts.push_back(path);
    expectError([&] { loadGltf(path); }, parts);
}

const float kNan = std::numeric_limits<float>::quiet_NaN();

INSTANTIATE_TEST_SUITE_P(
    Animation, MalformedAnimation,
    ::testing::Values(
        BadAnimation{"BadSampler", [](Doc& d) {
                         d.animate(0, "translation", "LINEAR", {0}, {0, 0, 0});
                         d.gltf["animations"][0]["channels"][0]["sampler"] = 3;
                     }, {"animation 'bob' channel 0: sampler: 3 out of range (1 samplers)"}},
        BadAnimation{"NodeOutOfRange", [](Doc& d) { d.animate(7, "translation", "LINEAR", {0}, {0, 0, 0}); },
                     {"animation 'bob' channel 0: target.node: 7 out of range (1 nodes)"}},
        BadAnimation{"UnnamedAnimation", [](Doc& d) { d.animate(-4, "translation", "LINEAR", {0}, {0, 0, 0}, ""); },
                     {"animation 0 channel 0: target.node: -4 out of range"}},
        BadAnimation{"UnknownPath", [](Doc& d) { d.animate(0, "colour", "LINEAR", {0}, {0, 0, 0}); },
                     {"channel 0: target.path: 'colour' unknown"}},
        BadAnimation{"DecreasingTimes", [](Doc& d) { d.animate(0, "translation", "LINEAR", {0, 2, 1}, std::vector<float>(9, 0)); },
                     {"channel 0: sampler 0 input: time 2 (1) is not after the previous (2)"}},
        BadAnimation{"NegativeTime", [](Doc& d) { d.animate(0, "translation", "LINEAR", {-1}, {0, 0, 0}); },
                     {"channel 0: sampler 0 input: time 0 (-1)"}},
        BadAnimation{"InputNotScalar", [](Doc& d) {
                         d.animate(0, "translation", "LINEAR", {0}, {0, 0, 0});
                         d.gltf["animations"][0]["samplers"][0]["input"] = 0;  // the VEC3 positions
                     }, {"channel 0: sampler 0 input: accessor 0: expected FLOAT SCALAR, got FLOAT VEC3"}},
        BadAnimation{"NanOutput", [](Doc& d) { d.animate(0, "scale", "LINEAR", {0, 1}, {1, 1, 1, 1, kNan, 1}); },
                     {"channel 0: sampler 0 output: value 1 is not finite"}},
        BadAnimation{"CountMismatch", [](Doc& d) { d.animate(0, "translation", "LINEAR", {0, 1, 2}, {0, 0, 0, 1, 1, 1}); },
                     {"channel 0: sampler 0 output: count 2, expected 3"}},
        BadAnimation{"CubicCountMismatch", [](Doc& d) { d.animate(0, "translation", "CUBICSPLINE", {0, 1}, std::vector<float>(6, 0)); },
                     {"channel 0: sampler 0 output: count 2, expected 6 (in-tangent, value, out-tangent per input time)"}},
        BadAnimation{"ZeroQuaternion", [](Doc& d) { d.animate(0, "rotation", "LINEAR", {0, 1}, {0, 0, 0, 1, 0, 0, 0, 0}); },
                     {"channel 0: sampler 0 output: value 1 is a zero quaternion"}},
        BadAnimation{"UnknownInterpolation", [](Doc& d) { d.animate(0, "translation", "SMOOTH", {0}, {0, 0, 0}); },
                     {"channel 0: sampler 0 interpolation: 'SMOOTH' unknown"}},
        BadAnimation{"MatrixNodeTargeted", [](Doc& d) {
                         d.gltf["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
                         d.animate(0, "translation", "LINEAR", {0}, {0, 0, 0});
                     }, {"animation 'bob' channel 0: target.node: node 0 has a matrix"}}),
    [](const ::testing::TestParamInfo<BadAnimation>& info) { return std::string(info.param.name); });
