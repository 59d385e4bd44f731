// `ppr fit`'s region search (engine/scene/planar_regions.hpp): one mesh split into its flat regions,
// regions joined across draws, two-sided panes, material selection, the area threshold, unique names,
// and the default scene, where it finds every hand-authored reflector.
#include "scene/planar_regions.hpp"
#include "scene/reflector_fit.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

using namespace ppr::scene;

namespace {

// A scene built triangle by triangle: each draw is one mesh with one material, identity transform.
struct SceneBuilder {
    Scene scene;
    int material(const std::string& name, bool transparent = false) {
        Material m;
        m.name = name;
        m.transparent = transparent;
        scene.materials.push_back(m);
        return int(scene.materials.size()) - 1;
    }
    void draw(const std::string& node, int material, const std::vector<glm::vec3>& triangleVertices) {
        Mesh mesh;
        mesh.firstIndex = uint32_t(scene.indices.size());
        mesh.indexCount = uint32_t(triangleVertices.size());
        mesh.vertexOffset = int32_t(scene.vertices.size());
        mesh.material = material;
        for (uint32_t i = 0; i < triangleVertices.size(); ++i) {
            scene.vertices.push_back(Vertex{triangleVertices[i], glm::vec3(0, 1, 0), glm::vec4(1, 0, 0, 1), glm::vec2(0)});
            scene.indices.push_back(i);
        }
        scene.meshes.push_back(mesh);
        DrawItem d;
        d.mesh = uint32_t(scene.meshes.size()) - 1;
        d.nodeName = node;
        scene.draws.push_back(d);
    }
};

// Two triangles, counter-clockwise seen from `up`: the quad of corners o, o+u, o+u+v, o+v.
std::vector<glm::vec3> quad(glm::vec3 o, glm::vec3 u, glm::vec3 v) { return {o, o + u, o + u + v, o, o + u + v, o + v}; }
std::vector<glm::vec3> join(std::vector<glm::vec3> a, const std::vector<glm::vec3>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}
std::vector<glm::vec3> flipped(std::vector<glm::vec3> t) {
    for (size_t i = 0; i + 2 < t.size(); i += 3) std::swap(t[i + 1], t[i + 2]);
    return t;
}

PlanarRegionOptions allMaterials(const Scene& s, float minArea = 0.0f) {
    PlanarRegionOptions o;
    o.materials.assign(s.materials.size(), true);
    o.minArea = minArea;
    return o;
}

const FittedRegion* byName(const PlanarRegionResult& r, const std::string& name) {
    for (const FittedRegion& f : r.regions)
        if (f.reflector.name == name) return &f;
    return nullptr;
}

}  // namespace

TEST(PlanarRegions, OneMeshSplitsIntoItsFlatRegions) {
    // A room corner as one mesh: a 4x3 floor, a 4x2 wall standing on its back edge, and a 1x1 table
    // top 0.8 m above the floor (not touching it): three regions, three planes.
    SceneBuilder b;
    const int m = b.material("stone");
    const std::vector<glm::vec3> floor = quad({0, 0, 3}, {4, 0, 0}, {0, 0, -3});
    const std::vector<glm::vec3> wall = quad({0, 0, 0}, {4, 0, 0}, {0, 2, 0});
    const std::vector<glm::vec3> table = quad({1, 0.8f, 2}, {1, 0, 0}, {0, 0, -1});
    b.draw("room", m, join(join(floor, wall), table));
    const PlanarRegionResult r = fitPlanarRegions(b.scene, allMaterials(b.scene));
    ASSERT_EQ(r.regions.size(), 3u);
    // Largest first; parts of one draw are numbered (none of them is the whole draw).
    EXPECT_EQ(r.regions[0].reflector.name, "room_1");
    EXPECT_EQ(r.regions[1].reflector.name, "room_2");
    EXPECT_EQ(r.regions[2].reflector.name, "room_3");
    EXPECT_FALSE(r.regions[0].wholeDraw);
    EXPECT_NEAR(r.regions[0].area, 12.0, 1e-4);
    EXPECT_NEAR(r.regions[0].reflector.normal.y, 1.0f, 1e-5f);
    EXPECT_NEAR(r.regions[1].area, 8.0, 1e-4);
    EXPECT_NEAR(r.regions[1].reflector.normal.z, 1.0f, 1e-5f);
    EXPECT_NEAR(r.regions[2].area, 1.0, 1e-4);
    EXPECT_NEAR(r.regions[2].reflector.center.y, 0.8f, 1e-5f);
    for (const FittedRegion& f : r.regions) {
        EXPECT_EQ(f.triangles, 2u);
        EXPECT_NEAR(f.area / f.rectangleArea, 1.0, 1e-4);
        EXPECT_LT(f.maxPlaneDistance, 1e-5);
        EXPECT_EQ(validateReflector(f.reflector), "");
    }
}

TEST(PlanarRegions, RegionsJoinAcrossDrawsButNotAcrossMaterials) {
    // One floor exported as two meshes sharing an edge: one region, named after the larger draw. A
    // third quad beside it in another material stays apart.
    SceneBuilder b;
    const int stone = b.material("stone"), water = b.material("water");
    b.draw("floor_west", stone, quad({0, 0, 2}, {1, 0, 0}, {0, 0, -2}));
    b.draw("floor_east", stone, quad({1, 0, 2}, {3, 0, 0}, {0, 0, -2}));
    b.draw("pool", water, quad({4, 0, 2}, {1, 0, 0}, {0, 0, -2}));
    const PlanarRegionResult r = fitPlanarRegions(b.scene, allMaterials(b.scene));
    ASSERT_EQ(r.regions.size(), 2u);
    const FittedRegion* floor = byName(r, "floor_east");  // the whole of its largest draw: its name
    ASSERT_TRUE(floor);
    EXPECT_TRUE(floor->wholeDraw);
    EXPECT_EQ(floor->triangles, 4u);
    EXPECT_NEAR(floor->area, 8.0, 1e-4);
    EXPECT_NEAR(floor->reflector.halfExtents.x, 2.0f, 1e-5f);
    EXPECT_NEAR(floor->reflector.halfExtents.y, 1.0f, 1e-5f);
    ASSERT_TRUE(byName(r, "pool"));
    EXPECT_EQ(byName(r, "pool")->material, water);
}

TEST(PlanarRegions, TwoSidedPaneIsOneGlassRegion) {
    SceneBuilder b;
    const int glass = b.material("glass", true);
    const std::vector<glm::vec3> front = quad({0, 0, 0}, {2, 0, 0}, {0, 1.5f, 0});
    b.draw("pane", glass, join(front, flipped(front)));
    const PlanarRegionResult r = fitPlanarRegions(b.scene, allMaterials(b.scene));
    ASSERT_EQ(r.regions.size(), 1u);
    EXPECT_EQ(r.regions[0].reflector.kind, ReflectorKind::Glass);
    EXPECT_EQ(r.regions[0].triangles, 4u);
    EXPECT_NEAR(std::abs(r.regions[0].reflector.normal.z), 1.0f, 1e-5f);
}

TEST(PlanarRegions, SelectionAreaAndCurvature) {
    SceneBuilder b;
    const int stone = b.material("stone"), brick = b.material("brick");
    b.draw("big", stone, quad({0, 0, 0}, {2, 0, 0}, {0, 0, -2}));
    b.draw("small", stone, quad({5, 0, 0}, {0.1f, 0, 0}, {0, 0, -0.1f}));
    b.draw("wall", brick, quad({0, 0, 0}, {2, 0, 0}, {0, 2, 0}));
    // A shallow roof: two quads meeting at a 1° ridge are not coplanar, so two regions.
    const float rise = std::tan(glm::radians(1.0f)) * 2.0f;
    b.draw("roof", stone, join(quad({10, 0, 0}, {2, rise, 0}, {0, 0, -2}), quad({12, rise, 0}, {2, -rise, 0}, {0, 0, -2})));

    PlanarRegionOptions o = allMaterials(b.scene, 0.05f);
    o.materials[size_t(brick)] = false;
    const PlanarRegionResult r = fitPlanarRegions(b.scene, o);
    EXPECT_TRUE(byName(r, "big"));
    EXPECT_FALSE(byName(r, "small"));  // 0.01 m² < 0.05
    EXPECT_FALSE(byName(r, "wall"));   // material not selected
    EXPECT_TRUE(byName(r, "roof_1"));
    EXPECT_TRUE(byName(r, "roof_2"));
    EXPECT_EQ(r.droppedSmall, 1u);
    EXPECT_EQ(r.regions.size(), 3u);
}

TEST(PlanarRegions, DefaultSceneFindsEveryAuthoredReflector) {
    const std::filesystem::path gltf = PPR_DEFAULT_SCENE_FILE;
    const Scene scene = loadGltf(gltf.string());
    const std::vector<Reflector> authored = loadReflectorFile((gltf.parent_path() / "default.reflectors.json").string());
    PlanarRegionOptions o;
    for (const Material& m : scene.materials) o.materials.push_back(m.reflective);
    const PlanarRegionResult r = fitPlanarRegions(scene, o);  // the default --min-area
    for (const Reflector& a : authored) {
        SCOPED_TRACE(a.name);
        const FittedRegion* f = byName(r, a.name);
        ASSERT_TRUE(f) << a.name << " not found";
        EXPECT_TRUE(f->wholeDraw);
        EXPECT_EQ(validateReflector(f->reflector), "");
        EXPECT_EQ(f->reflector.kind, a.kind);
        EXPECT_LE(glm::length(f->reflector.center - a.center), 1e-4f);
        EXPECT_GE(glm::dot(f->reflector.normal, a.normal), 0.9999f);
        EXPECT_NEAR(f->rectangleArea, 4.0 * a.halfExtents.x * a.halfExtents.y, 1e-3 * f->rectangleArea);
    }
    // The one region beyond the authored set: the steel post's flat top (its side is curved, so the
    // editor's per-draw fit refuses the post as a whole).
    ASSERT_EQ(r.regions.size(), authored.size() + 1);
    const FittedRegion* cap = byName(r, "post_steel_1");  // a part of the post's draw: numbered
    ASSERT_TRUE(cap);
    EXPECT_GE(cap->reflector.normal.y, 0.9999f);
    EXPECT_GT(r.droppedSmall, 100u);  // the sphere's and the post's facets
}
