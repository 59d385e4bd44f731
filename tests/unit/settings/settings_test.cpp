// Settings declared once: every key parses its default, round-trips its text, rejects what is out of
// range with a message naming the key, and decodes into the typed FrameSettings the passes read.
#include "common/frame.h"
#include "frame/depth_prepass.hpp"
#include "frame/shadow_map_work.hpp"
#include "ppr_reflect/ppr_reflect.h"
#include "settings/debug_views.hpp"
#include "settings/settings.hpp"

#include <gtest/gtest.h>

#include <set>

using namespace ppr::app;

TEST(Settings, EveryDeclarationIsCompleteAndUnique) {
    std::set<std::string> keys;
    for (const SettingDecl& d : settingDecls()) {
        EXPECT_TRUE(keys.insert(d.key).second) << "duplicate key " << d.key;
        EXPECT_FALSE(d.help.empty()) << d.key;
        EXPECT_FALSE(d.owner.empty()) << d.key;
        EXPECT_TRUE(d.read && d.write) << d.key;
        if (d.kind == SettingKind::Toggle) EXPECT_EQ(d.choices, (std::vector<std::string>{"0", "1"})) << d.key;
        if (d.kind == SettingKind::Number || d.kind == SettingKind::Integer) EXPECT_LT(d.min, d.max) << d.key;
    }
    // The keys the DESIGN contract names.
    for (const char* k : {"holes", "filter", "antibleed", "tiles", "indirect", "glass", "debug"}) EXPECT_TRUE(keys.count(k)) << k;
}

TEST(Settings, DefaultsReadBackAsDeclared) {
    const Settings s;
    for (const SettingDecl& d : settingDecls()) EXPECT_EQ(s.get(d.key), d.defaultValue) << d.key;
    EXPECT_EQ(s.canonicalTexts().size(), settingDecls().size());
}

// PPR's contact march tests its taps with ssr-brute's default thickness (ppr_reflect.h): the two
// declarations must not drift apart.
TEST(Settings, ContactMarchThicknessIsTheSsrDefault) {
    const Settings s;
    const FrameSettings& v = s.values();
    EXPECT_EQ(v.ssr.thickness, ppr::gpu::kPprContactThickness);
    EXPECT_EQ(v.ssr.thicknessScale, ppr::gpu::kPprContactThicknessScale);
}

TEST(Settings, DecodesIntoTypedFields) {
    Settings s;
    const FrameSettings& v = s.values();
    EXPECT_EQ(v.ppr.holes, HoleRule::Enclosed);
    EXPECT_TRUE(v.ppr.facing && v.ppr.filter && v.ppr.antibleed && v.ppr.tiles && v.tiles.indirect && v.glass.enabled);
    EXPECT_EQ(v.ppr.fallback, PprFallback::SsrHoles);
    EXPECT_FLOAT_EQ(v.ssr.distance, 40.0f);
    EXPECT_EQ(v.ssr.thickness, 0.05f);
    EXPECT_EQ(v.ssr.steps, 4096u);
    EXPECT_EQ(v.glass.atlas, 1024u);
    EXPECT_EQ(v.view.shadowRes, 2048u);
    EXPECT_EQ(v.view.debug, ppr::gpu::kDebugNone);
    s.apply("holes=0");
    s.apply("fallback=none");
    s.apply("ssr_thickness=0.125");
    s.apply("glass_atlas=256");
    s.apply("debug=shadow");
    EXPECT_EQ(v.ppr.holes, HoleRule::Off);
    s.apply("holes=slides");
    EXPECT_EQ(v.ppr.holes, HoleRule::Slides);
    EXPECT_EQ(v.ppr.fallback, PprFallback::None);
    EXPECT_EQ(v.ssr.thickness, 0.125f);
    EXPECT_EQ(v.glass.atlas, 256u);
    EXPECT_EQ(v.view.debug, ppr::gpu::kDebugShadow);
    EXPECT_EQ(s.get("ssr_thickness"), "0.125");
    EXPECT_EQ(s.get("debug"), "shadow");
    EXPECT_EQ(v.ppr.projectThreads, 0u);  // auto: the pass picks by device
    s.apply("project_threads=128");
    EXPECT_EQ(v.ppr.projectThreads, 128u);
    EXPECT_EQ(s.get("project_threads"), "128");
    s.apply("project_threads=auto");
    EXPECT_EQ(v.ppr.projectThreads, 0u);
    EXPECT_EQ(v.ppr.reachThreads, 0u);
    s.apply("reach_threads=16");
    EXPECT_EQ(v.ppr.reachThreads, 16u);
    EXPECT_EQ(s.get("reach_threads"), "16");
    EXPECT_EQ(v.tiles.classifyThreads, 0u);
    s.apply("classify_threads=64");
    EXPECT_EQ(v.tiles.classifyThreads, 64u);
    EXPECT_EQ(s.get("classify_threads"), "64");
    EXPECT_EQ(v.ssr.hizThreads, 0u);
    s.apply("hiz_threads=256");
    EXPECT_EQ(v.ssr.hizThreads, 256u);
    EXPECT_EQ(s.get("hiz_threads"), "256");
}

TEST(Settings, FloatTextRoundTrips) {
    Settings s;
    s.set("exposure", "0.3");
    EXPECT_EQ(s.get("exposure"), "0.3");  // printed as the float it is, not as a widened double
    EXPECT_EQ(static_cast<float>(s.number("exposure")), 0.3f);
}

void expectRejected(const std::string& assignment, const std::string& fragment) {
    Settings s;
    const Settings before = s;
    try {
        s.apply(assignment);
        FAIL() << assignment << " was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
    EXPECT_EQ(s.canonicalTexts(), before.canonicalTexts()) << "a rejected value must change nothing";
}

TEST(Settings, RejectsBadValuesNamingKeyAndWhatIsAccepted) {
    expectRejected("colour=red", "known keys: debug");
    expectRejected("holes=2", "expected one of 0|1|slides");
    expectRejected("debug=sparkles", "expected one of none|albedo");
    expectRejected("ssr_distance=nan", "ssr_distance=nan: expected a number in [0.1, 1000]");
    expectRejected("ssr_distance=1e9", "expected a number");
    expectRejected("ssr_steps=2.5", "ssr_steps=2.5: expected a whole number in [1, 65536]");
    expectRejected("glass_atlas=", "expected a whole number");
    expectRejected("exposure=1x", "expected a number");
    expectRejected("project_threads=48", "project_threads=48: expected one of auto|32|64|128|256");
    expectRejected("classify_threads=32", "classify_threads=32: expected one of auto|1|16|64");
    expectRejected("hiz_threads=4", "hiz_threads=4: expected one of auto|16|64|256");
    expectRejected("novalue", "expected key=value");
    expectRejected("=1", "expected key=value");
}

TEST(Settings, UsageListsEveryKeyWithItsDefaultAndOwner) {
    const std::string usage = settingsUsage();
    for (const SettingDecl& d : settingDecls())
        EXPECT_NE(usage.find("    " + d.key + "="), std::string::npos) << d.key << "\n" << usage;
    EXPECT_NE(usage.find("holes=0|1|slides (default 1; ppr)"), std::string::npos) << usage;
    EXPECT_NE(usage.find("glass_atlas=[64, 8192] (default 1024; glass)"), std::string::npos) << usage;
}

TEST(DebugViews, EveryShaderConstantIsNamedOnce) {
    std::set<uint32_t> values;
    std::set<std::string> names;
    for (const DebugViewDecl& v : debugViews()) {
        EXPECT_TRUE(values.insert(v.value).second) << v.name;
        EXPECT_TRUE(names.insert(v.name).second) << v.name;
        EXPECT_LT(v.value, ppr::gpu::kDebugViewCount) << v.name;
        EXPECT_FALSE(v.help.empty()) << v.name;
    }
    EXPECT_EQ(values.size(), ppr::gpu::kDebugViewCount);  // kDebugShadow included: every view is selectable
    EXPECT_EQ(debugView(ppr::gpu::kDebugAtlas).name, "atlas");
    EXPECT_THROW(debugView(ppr::gpu::kDebugViewCount), std::logic_error);
}

TEST(DebugViews, TheDebugSettingOffersExactlyTheTable) {
    const SettingDecl* debug = findSetting("debug");
    ASSERT_NE(debug, nullptr);
    std::vector<std::string> names;
    for (const DebugViewDecl& v : debugViews()) names.push_back(v.name);
    EXPECT_EQ(debug->choices, names);
    Settings s;
    for (const DebugViewDecl& v : debugViews()) {
        s.set("debug", v.name);
        EXPECT_EQ(s.values().view.debug, v.value) << v.name;
    }
}

// depth_prepass: 0 and 1 are what they say; auto draws the pre-pass while the opaque triangles number
// at most a quarter of the pixels (the default scene at 1280x720: yes; the scale scene: no).
TEST(DepthPrepass, AutoWeighsTrianglesAgainstPixels) {
    const uint64_t pixels720 = 1280u * 720u;
    EXPECT_TRUE(depthPrepassWanted(DepthPrepass::Auto, 20589, pixels720));
    EXPECT_FALSE(depthPrepassWanted(DepthPrepass::Auto, 1115138, pixels720));
    EXPECT_TRUE(depthPrepassWanted(DepthPrepass::Auto, pixels720 / 4, pixels720));
    EXPECT_FALSE(depthPrepassWanted(DepthPrepass::Auto, pixels720 / 4 + 1, pixels720));
    EXPECT_TRUE(depthPrepassWanted(DepthPrepass::Auto, 1115138, 3840u * 2160u));  // 4K: enough pixels
    EXPECT_TRUE(depthPrepassWanted(DepthPrepass::On, 1115138, pixels720));
    EXPECT_FALSE(depthPrepassWanted(DepthPrepass::Off, 0, pixels720));
    Settings s;
    EXPECT_EQ(s.values().view.depthPrepass, DepthPrepass::Auto);
    s.set("depth_prepass", "0");
    EXPECT_EQ(s.values().view.depthPrepass, DepthPrepass::Off);
    s.set("depth_prepass", "1");
    EXPECT_EQ(s.values().view.depthPrepass, DepthPrepass::On);
}

TEST(ShadowCache, DrawsTheKeptMapsOnlyWhenWhatCastsThemChanges) {
    const ShadowMapKey rest{2048, std::nullopt}, raised{2048, 1.0};
    // The first frame draws everything; a still scene has no frame map of its own.
    EXPECT_EQ(shadowMapWork(std::nullopt, rest, true), (ShadowMapWork{true, true}));
    EXPECT_EQ(shadowMapWork(std::nullopt, rest, false), (ShadowMapWork{true, false}));
    // Nothing moved: nothing to draw.
    EXPECT_EQ(shadowMapWork(rest, rest, true), (ShadowMapWork{false, false}));
    EXPECT_EQ(shadowMapWork(raised, raised, true), (ShadowMapWork{false, false}));
    // The animation clock moved: only the moving casters, over the kept still map.
    EXPECT_EQ(shadowMapWork(rest, raised, true), (ShadowMapWork{false, true}));
    EXPECT_EQ(shadowMapWork(raised, ShadowMapKey{2048, 1.5}, true), (ShadowMapWork{false, true}));
    EXPECT_EQ(shadowMapWork(raised, rest, true), (ShadowMapWork{false, true}));
    // A new resolution: both maps again.
    EXPECT_EQ(shadowMapWork(rest, ShadowMapKey{1024, std::nullopt}, true), (ShadowMapWork{true, true}));
    EXPECT_EQ(shadowMapWork(rest, ShadowMapKey{1024, std::nullopt}, false), (ShadowMapWork{true, false}));
    Settings s;
    EXPECT_TRUE(s.values().view.shadowCache);
    s.set("shadow_cache", "0");
    EXPECT_FALSE(s.values().view.shadowCache);
}

TEST(ShadowCache, TheViewerSaysWhetherTheFrameReadsAKeptMap) {
    EXPECT_EQ(shadowMapSummary(false, true, 5, 7), "shadow map: drawn every frame (shadow_cache=0)");
    EXPECT_EQ(shadowMapSummary(true, false, 1, 0), "shadow map: kept; still casters drawn 1 time");
    EXPECT_EQ(shadowMapSummary(true, true, 2, 150), "shadow map: kept; still casters drawn 2 times, moving ones 150");
}
