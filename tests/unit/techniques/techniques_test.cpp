// Which passes count as a technique's cost (report.json technique_gpu_ms, compare, bench): the pure
// naming rules of the technique table (app/techniques/technique_table.cpp).
#include "techniques/technique_table.hpp"

#include <gtest/gtest.h>

using namespace ppr::app;

TEST(Techniques, ListsEveryTechniqueInUiOrder) {
    const std::vector<std::string> expected = {"ppr", "ssr-brute", "ssr-lowq", "ssr-hiz", "ssr-linear", "planar", "raytraced", "floor", "none"};
    EXPECT_EQ(techniqueNames(), expected);
    EXPECT_TRUE(isTechnique("ssr-linear"));
    EXPECT_FALSE(isTechnique("ssr"));
    EXPECT_TRUE(isSsrTechnique("ssr-hiz"));
    EXPECT_FALSE(isSsrTechnique("ppr"));
    EXPECT_FALSE(isSsrTechnique("ssr-nonsense"));
}

TEST(Techniques, OwnPassesCount) {
    EXPECT_TRUE(isTechniquePass("ppr", "ppr.project"));
    EXPECT_TRUE(isTechniquePass("ppr", "ppr.fallback"));
    EXPECT_TRUE(isTechniquePass("planar", "planar.gbuffer.3"));
    EXPECT_TRUE(isTechniquePass("ssr-brute", "ssr-brute.planar"));
    EXPECT_TRUE(isTechniquePass("ssr-brute", "ssr-brute"));  // the whole-screen pass (indirect=0)
    EXPECT_TRUE(isTechniquePass("floor", "floor"));
    EXPECT_FALSE(isTechniquePass("ssr-brute", "ssr-brute-x"));
    EXPECT_FALSE(isTechniquePass("ssr-lowq", "ssr-brute.planar"));
}

TEST(Techniques, SharedPassesCountWhereTheTechniqueNeedsThem) {
    // Tile classification: PPR and the SSR family.
    for (const char* t : {"ppr", "ssr-brute", "ssr-lowq", "ssr-hiz", "ssr-linear"}) EXPECT_TRUE(isTechniquePass(t, "tiles.classify")) << t;
    for (const char* t : {"planar", "floor", "none"}) EXPECT_FALSE(isTechniquePass(t, "tiles.classify")) << t;
    // The depth hierarchy: ssr-hiz and PPR's fallback only.
    EXPECT_TRUE(isTechniquePass("ssr-hiz", "hiz.build.0"));
    EXPECT_TRUE(isTechniquePass("ppr", "hiz.build"));
    for (const char* t : {"ssr-brute", "ssr-lowq", "ssr-linear", "planar", "floor"}) EXPECT_FALSE(isTechniquePass(t, "hiz.build.0")) << t;
    // Frame passes belong to nobody.
    for (const std::string& t : techniqueNames()) {
        EXPECT_FALSE(isTechniquePass(t, "gbuffer")) << t;
        EXPECT_FALSE(isTechniquePass(t, "composite")) << t;
    }
    EXPECT_FALSE(isTechniquePass("none", "none"));
}
