#include "default_scene.hpp"

#include "scene/reflector_fit.hpp"

#include "gltf_writer.hpp"
#include "mesh_builder.hpp"
#include "textures.hpp"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>

// Layout (metres, +Y up; north = −Z, east = +X):
//   north wall (brick) at z = −11 with a 6 × 3 m mirror facing +Z, flanked by two round pillars;
//   west wall (brick) at x = −11 with a six-step marble staircase rising north to a terrace;
//   a square brick pillar with a flowerpot in front of it behind a puddle (the slides' case);
//   a large central puddle for grazing views, two tinted glass panels (one facing −X, one oblique)
//   in the east, coloured boxes and spheres as recognisable reflection content.
// The sun is expected from above the south-east, so the wall faces and the mirror side are lit.

namespace gen {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr float kPuddleY = 0.003f;  // just above the floor to avoid depth fighting

Json reflectorJson(const ReflectorDesc& r) {
    Json j;
    j["name"] = r.name;
    j["center"] = vec(r.center);
    j["normal"] = vec(r.normal);
    j["tangent"] = vec(r.tangent);
    j["half_extents"] = Json::array({num(r.halfExtents.x), num(r.halfExtents.y)});
    j["kind"] = r.glass ? "glass" : "opaque";
    j["reflectance"] = num(r.reflectance);
    return j;
}

// Moves a mesh built in world coordinates (so its UVs are world-projected and adjacent objects
// do not repeat the same texture patch) into the space of a node placed at `t`.
MeshData toNode(MeshData m, const glm::dvec3& t) {
    transformMesh(m, glm::mat3(1.0f), -glm::vec3(t));
    return m;
}

// Rotation taking panel space (X = tangent, Y = up, Z = normal) to world.
glm::mat3 panelBasis(const glm::dvec3& tangent, const glm::dvec3& normal) {
    return glm::mat3(glm::vec3(tangent), glm::vec3(0, 1, 0), glm::vec3(normal));
}

class Layout {
public:
    explicit Layout(GltfWriter& w) : w_(w) {}

    int mesh(MeshData m, const std::string& name, int material) {
        m.name = name;
        return w_.addMesh(m, material);
    }

    // Ordinary geometry, optionally turned about +Y by `yawDeg` (counter-clockwise seen from above).
    int object(const std::string& name, int mesh, const glm::dvec3& t, double yawDeg = 0.0) {
        NodeDesc n;
        n.name = name;
        n.mesh = mesh;
        n.translation = t;
        if (yawDeg != 0.0) n.rotation = glm::angleAxis(yawDeg * kDeg, glm::dvec3(0, 1, 0));
        return w_.addNode(n);
    }

    // Node `node` (at rest at `t`) rises `height` metres and comes back every `period` seconds: a
    // raised cosine in `keys` LINEAR keys, so time 0 and the end of each loop are the rest pose.
    void bob(const std::string& name, int node, const glm::dvec3& t, double height, double period, int keys) {
        AnimationDesc a;
        a.name = name;
        a.node = node;
        a.path = "translation";
        for (int k = 0; k < keys; ++k) {
            const double time = period * k / (keys - 1);
            const double y = t.y + 0.5 * height * (1.0 - std::cos(2.0 * kPi * time / period));
            a.times.push_back(static_cast<float>(time));
            a.values.insert(a.values.end(), {static_cast<float>(t.x), static_cast<float>(y), static_cast<float>(t.z)});
        }
        w_.addAnimation(std::move(a));
    }

    // A reflective surface: node at `t` with no rotation, reflector given in node space. Refuses
    // geometry that leaves the reflector's rectangle or plane, so content and reflectors agree.
    void reflective(const std::string& name, int mesh, const glm::dvec3& t, ReflectorDesc r) {
        r.name = name;
        const glm::dvec3 b = glm::cross(r.normal, r.tangent);
        for (const glm::vec3& p : w_.mesh(mesh).positions) {
            const glm::dvec3 d = glm::dvec3(p) - r.center;
            if (std::fabs(glm::dot(d, r.normal)) > 1e-4 || std::fabs(glm::dot(d, r.tangent)) > r.halfExtents.x + 1e-4 ||
                std::fabs(glm::dot(d, b)) > r.halfExtents.y + 1e-4)
                throw std::logic_error("reflective mesh " + name + " leaves its reflector rectangle");
        }
        NodeDesc n;
        n.name = name;
        n.mesh = mesh;
        n.translation = t;
        n.extras = Json{{"ppr_reflector", reflectorJson(r)}};
        w_.addNode(n);
        ReflectorDesc world = r;
        world.center += t;
        worldReflectors.push_back(world);
    }

    void camera(const std::string& name, const glm::dvec3& pos, double yawDeg, double pitchDeg) { w_.addCameraNode(name, pos, yawDeg, pitchDeg); }

    std::vector<ReflectorDesc> worldReflectors;

private:
    GltfWriter& w_;
};

struct Materials {
    int floor, brick, sandstone, marble, water, mirror, glass, frame;
    int red, blue, yellow, green, teal, orange, white, terracotta, soil, leaves;
    int chrome, satinSteel;  // reflective but curved: no reflector rectangle fits them
    int waterRippled, tilesPolished, mirrorWavy;  // normal-mapped reflectors (the south corner)
};

// Texture repeat sizes in metres: 0.75 m floor slabs, 0.3 × 0.15 m bricks, 0.5 × 0.25 m blocks.
constexpr float kFloorTex = 3.0f, kBrickTex = 1.2f, kStoneTex = 1.0f, kMarbleTex = 1.2f;

Materials createMaterials(GltfWriter& w, const std::string& dir) {
    auto writeSet = [&](const std::string& stem, const TextureSet& set, int& base, int& normal, int& mr) {
        writePng(dir + "/" + stem + "_basecolor.png", set.baseColor);
        writePng(dir + "/" + stem + "_normal.png", set.normal);
        writePng(dir + "/" + stem + "_mr.png", set.metallicRoughness);
        base = w.addTexture(stem + "_basecolor.png");
        normal = w.addTexture(stem + "_normal.png");
        mr = w.addTexture(stem + "_mr.png");
    };
    auto textured = [&](const std::string& name, const std::string& stem, const TextureSet& set) {
        MaterialDesc m;
        m.name = name;
        writeSet(stem, set, m.baseColorTexture, m.normalTexture, m.metallicRoughnessTexture);
        m.metallic = 0.0f;  // dielectrics; roughness comes from the texture's G channel
        m.roughness = 1.0f;
        return w.addMaterial(m);
    };
    auto plain = [&](const std::string& name, glm::vec4 color, float roughness, float metallic = 0.0f,
                     bool reflective = false) {
        MaterialDesc m;
        m.name = name;
        m.baseColor = color;
        m.roughness = roughness;
        m.metallic = metallic;
        m.reflective = reflective;
        return w.addMaterial(m);
    };

    Materials M{};
    M.floor = textured("floor_stone", "floor", floorTiles(512));
    M.brick = textured("brick", "brick", bricks(512));
    M.sandstone = textured("sandstone", "sandstone", sandstone(256));
    {
        writePng(dir + "/marble_basecolor.png", marble(256));
        MaterialDesc m;
        m.name = "marble_polished_dark";
        m.baseColorTexture = w.addTexture("marble_basecolor.png");
        m.roughness = 0.06f;
        m.reflective = true;
        M.marble = w.addMaterial(m);
    }
    // Factors are linear. Reflective surfaces are dark/neutral so the reflection carries the image.
    M.water = plain("puddle_water", {0.02f, 0.025f, 0.03f, 1.0f}, 0.05f, 0.0f, true);
    M.mirror = plain("mirror", {0.90f, 0.91f, 0.93f, 1.0f}, 0.02f, 1.0f, true);
    {
        // Transparent: drawn by the glass forward pass over the opaque scene, tinting what it lets through.
        MaterialDesc m;
        m.name = "glass_tinted";
        m.baseColor = {0.62f, 0.82f, 0.84f, 0.6f};
        m.roughness = 0.05f;
        m.reflective = true;
        m.transparent = true;
        M.glass = w.addMaterial(m);
    }
    M.frame = plain("frame_dark_metal", {0.10f, 0.10f, 0.11f, 1.0f}, 0.45f);
    M.red = plain("paint_red", {0.70f, 0.06f, 0.04f, 1.0f}, 0.45f);
    M.blue = plain("paint_blue", {0.05f, 0.16f, 0.70f, 1.0f}, 0.45f);
    M.yellow = plain("paint_yellow", {0.85f, 0.62f, 0.05f, 1.0f}, 0.5f);
    M.green = plain("paint_green", {0.08f, 0.45f, 0.12f, 1.0f}, 0.5f);
    M.teal = plain("paint_teal", {0.03f, 0.42f, 0.45f, 1.0f}, 0.35f);
    M.orange = plain("paint_orange", {0.90f, 0.30f, 0.03f, 1.0f}, 0.45f);
    M.white = plain("paint_white", {0.80f, 0.80f, 0.78f, 1.0f}, 0.5f);
    M.terracotta = plain("terracotta", {0.55f, 0.18f, 0.08f, 1.0f}, 0.8f);
    M.soil = plain("soil", {0.06f, 0.035f, 0.02f, 1.0f}, 1.0f);
    M.leaves = plain("leaves", {0.07f, 0.32f, 0.05f, 1.0f}, 0.7f);
    M.chrome = plain("chrome", {0.92f, 0.92f, 0.94f, 1.0f}, 0.03f, 1.0f, true);
    M.satinSteel = plain("steel_satin", {0.75f, 0.72f, 0.68f, 1.0f}, 0.3f, 1.0f, true);

    // Normal-mapped reflectors: flat rectangles whose surfaces are not perfect mirrors.
    auto normalMapped = [&](MaterialDesc m, const std::string& stem, const Image& normals) {
        writePng(dir + "/" + stem + "_normal.png", normals);
        m.normalTexture = w.addTexture(stem + "_normal.png");
        m.reflective = true;
        return w.addMaterial(m);
    };
    MaterialDesc water;
    water.name = "puddle_water_rippled";
    water.baseColor = {0.02f, 0.025f, 0.03f, 1.0f};
    water.roughness = 0.05f;
    M.waterRippled = normalMapped(water, "ripples", rippleNormals(256));
    {
        const TextureSet tiles = polishedTiles(512);
        writePng(dir + "/tiles_polished_basecolor.png", tiles.baseColor);
        writePng(dir + "/tiles_polished_mr.png", tiles.metallicRoughness);
        MaterialDesc m;
        m.name = "tiles_polished";
        m.baseColorTexture = w.addTexture("tiles_polished_basecolor.png");
        m.metallicRoughnessTexture = w.addTexture("tiles_polished_mr.png");
        m.roughness = 1.0f;  // the texture's G channel: glossy tops, rough grout
        M.tilesPolished = normalMapped(m, "tiles_polished", tiles.normal);
    }
    MaterialDesc wavy;
    wavy.name = "mirror_wavy";
    wavy.baseColor = {0.90f, 0.91f, 0.93f, 1.0f};
    wavy.roughness = 0.02f;
    wavy.metallic = 1.0f;
    M.mirrorWavy = normalMapped(wavy, "mirror_wavy", wavyGlassNormals(256));
    return M;
}

void buildWalls(Layout& L, const Materials& M) {
    MeshData floor;
    addQuad(floor, {-12, 0, 12}, {24, 0, 0}, {0, 0, -24}, kFloorTex);
    L.object("floor", L.mesh(floor, "floor", M.floor), {0, 0, 0});

    // North and west walls, 4.5 m high, with sandstone copings.
    MeshData north, west, coping;
    addBox(north, {-12.0f, 0.0f, -11.2f}, {12.0f, 4.5f, -10.8f}, kBrickTex, AllFaces & ~NegY);
    addBox(west, {-11.2f, 0.0f, -10.8f}, {-10.8f, 4.5f, 6.0f}, kBrickTex, AllFaces & ~NegY);
    addBox(coping, {-12.1f, 4.5f, -11.3f}, {12.1f, 4.68f, -10.7f}, kStoneTex, AllFaces);
    addBox(coping, {-11.3f, 4.5f, -10.7f}, {-10.7f, 4.68f, 6.1f}, kStoneTex, AllFaces);
    L.object("wall_north", L.mesh(toNode(north, {0, 0, -11}), "wall_north", M.brick), {0, 0, -11});
    L.object("wall_west", L.mesh(toNode(west, {-11, 0, -2.4}), "wall_west", M.brick), {-11, 0, -2.4});
    L.object("wall_copings", L.mesh(coping, "wall_copings", M.sandstone), {0, 0, 0});
}

void buildMirror(Layout& L, const Materials& M) {
    // 6 × 3 m mirror standing on a 0.25 m plinth in a dark frame, 14 cm in front of the wall.
    const glm::dvec3 c(0.0, 1.75, -10.66);
    MeshData frame;
    addBox(frame, {-3.2f, 0.0f, -10.8f}, {3.2f, 0.25f, -10.6f}, kStoneTex);
    addBox(frame, {-3.2f, 3.25f, -10.8f}, {3.2f, 3.45f, -10.6f}, kStoneTex);
    addBox(frame, {-3.2f, 0.25f, -10.8f}, {-3.0f, 3.25f, -10.6f}, kStoneTex);
    addBox(frame, {3.0f, 0.25f, -10.8f}, {3.2f, 3.25f, -10.6f}, kStoneTex);
    L.object("mirror_frame", L.mesh(frame, "mirror_frame", M.frame), {0, 0, 0});

    MeshData glassMesh;
    addQuad(glassMesh, {-3.0f, -1.5f, 0.0f}, {6.0f, 0.0f, 0.0f}, {0.0f, 3.0f, 0.0f}, 1.0f);
    ReflectorDesc r;
    r.normal = {0, 0, 1};
    r.tangent = {1, 0, 0};
    r.halfExtents = {3.0, 1.5};
    r.reflectance = 0.9;
    L.reflective("mirror", L.mesh(glassMesh, "mirror", M.mirror), c, r);
}

// Round sandstone pillar: plinth, shaft, capital. Returns a mesh in pillar-local space.
MeshData roundPillar(float shaftHeight) {
    MeshData m;
    addBox(m, {-0.4f, 0.0f, -0.4f}, {0.4f, 0.3f, 0.4f}, kStoneTex, AllFaces & ~NegY);
    addCylinder(m, {0.0f, 0.3f, 0.0f}, 0.28f, 0.25f, shaftHeight, 32, false, false, kStoneTex);
    addBox(m, {-0.38f, 0.3f + shaftHeight, -0.38f}, {0.38f, 0.55f + shaftHeight, 0.38f}, kStoneTex);
    return m;
}

void buildStairs(Layout& L, const Materials& M) {
    // Six steps rising north against the west wall to a terrace: 4.8 m wide, 0.6 m treads,
    // 0.15 m risers (shallow, so a raised camera sees past each riser in the tread below). Step bodies are plain sandstone without top faces; each tread is a separate
    // polished-marble node with its own reflector (parallel planes at six heights).
    const float x0 = -10.8f, x1 = -6.0f, zFront = -3.0f, tread = 0.6f, rise = 0.15f;
    const int steps = 6;
    MeshData body;
    for (int i = 0; i < steps; ++i) {
        const float zHi = zFront - tread * static_cast<float>(i), zLo = zHi - tread;
        addBox(body, {x0, 0.0f, zLo}, {x1, rise * static_cast<float>(i + 1), zHi}, kStoneTex, PosX | PosZ);
    }
    const float terraceZ = zFront - tread * steps, terraceY = rise * (steps + 1);
    addBox(body, {x0, 0.0f, -10.8f}, {x1, terraceY, terraceZ}, kStoneTex, PosX | PosY | PosZ);
    L.object("stairs", L.mesh(body, "stairs", M.sandstone), {0, 0, 0});

    const float cx = 0.5f * (x0 + x1), halfW = 0.5f * (x1 - x0);
    for (int i = 0; i < steps; ++i) {
        const glm::dvec3 t(cx, rise * static_cast<float>(i + 1), zFront - tread * (static_cast<float>(i) + 0.5f));
        MeshData top;
        addQuad(top, glm::vec3(t) + glm::vec3(-halfW, 0.0f, 0.5f * tread), {2 * halfW, 0, 0}, {0, 0, -tread}, kMarbleTex);
        ReflectorDesc r;
        r.normal = {0, 1, 0};
        r.tangent = {1, 0, 0};
        r.halfExtents = {halfW, 0.5 * tread};
        r.reflectance = 0.5;
        const std::string name = "step_" + std::to_string(i);
        L.reflective(name, L.mesh(toNode(top, t), name, M.marble), t, r);
    }

    // Terrace: two pillars framing the top of the stairs and a sphere on a pedestal, all tall
    // enough to show up in the treads; small objects standing on the treads themselves.
    const int pillar = L.mesh(roundPillar(2.6f), "pillar_terrace", M.sandstone);
    L.object("pillar_terrace_w", pillar, {-10.2, terraceY, -7.1});
    L.object("pillar_terrace_e", pillar, {-6.6, terraceY, -7.1});
    MeshData pedestal, globe;
    addBox(pedestal, {-0.4f, 0.0f, -0.4f}, {0.4f, 1.0f, 0.4f}, kStoneTex, AllFaces & ~NegY);
    addSphere(globe, {0.0f, 0.0f, 0.0f}, 0.55f, 48, 24, 1.0f);
    L.object("terrace_pedestal", L.mesh(pedestal, "terrace_pedestal", M.sandstone), {-8.4, terraceY, -8.6});
    L.object("terrace_globe", L.mesh(globe, "terrace_globe", M.teal), {-8.4, terraceY + 1.55, -8.6});

    MeshData cube, ball;
    addBox(cube, {-0.2f, 0.0f, -0.2f}, {0.2f, 0.4f, 0.2f}, 1.0f, AllFaces & ~NegY);
    addSphere(ball, {0.0f, 0.0f, 0.0f}, 0.2f, 32, 16, 1.0f);
    L.object("step_box", L.mesh(cube, "step_box", M.orange), {-7.0, rise * 2, zFront - tread * 1.5}, 20.0);
    L.object("step_ball", L.mesh(ball, "step_ball", M.white), {-9.5, rise * 4 + 0.2, zFront - tread * 3.5});
}

void buildFlowerpotCorner(Layout& L, const Materials& M) {
    // The slides' case: a flowerpot in front of a pillar, both reflected by the puddle in front,
    // so the pot's reflection must win over the pillar's behind it.
    MeshData pillar, cap;
    addBox(pillar, {-0.35f, 0.0f, -0.35f}, {0.35f, 3.8f, 0.35f}, kBrickTex, AllFaces & ~NegY);
    addBox(cap, {-0.42f, 3.8f, -0.42f}, {0.42f, 4.0f, 0.42f}, kStoneTex);
    L.object("pillar_brick", L.mesh(pillar, "pillar_brick", M.brick), {-3.2, 0, -2.4});
    L.object("pillar_brick_cap", L.mesh(cap, "pillar_brick_cap", M.sandstone), {-3.2, 0, -2.4});

    MeshData pot, soil, plant;
    addCylinder(pot, {0.0f, 0.0f, 0.0f}, 0.2f, 0.3f, 0.47f, 40, true, false, 1.0f);
    addCylinder(pot, {0.0f, 0.45f, 0.0f}, 0.335f, 0.335f, 0.09f, 40, true, true, 1.0f);
    addDisk(soil, {0.0f, 0.545f, 0.0f}, 0.29f, 40, true, 1.0f);
    // A clump of foliage spheres; offsets are fixed so the output is deterministic.
    const float leaves[][4] = {{0.0f, 0.85f, 0.0f, 0.30f},    {0.2f, 0.74f, 0.1f, 0.2f},  {-0.18f, 0.76f, 0.12f, 0.21f},
                               {0.05f, 0.75f, -0.2f, 0.2f},   {-0.1f, 1.08f, 0.0f, 0.2f}, {0.12f, 1.02f, 0.08f, 0.17f},
                               {-0.02f, 0.95f, 0.22f, 0.16f}, {0.16f, 0.9f, -0.14f, 0.16f}};
    for (const auto& s : leaves) addSphere(plant, {s[0], s[1], s[2]}, s[3], 24, 12, 0.5f);
    const glm::dvec3 potPos(-3.0, 0.0, -1.3);
    L.object("flowerpot", L.mesh(pot, "flowerpot", M.terracotta), potPos);
    L.object("flowerpot_soil", L.mesh(soil, "flowerpot_soil", M.soil), potPos);
    L.object("flowerpot_plant", L.mesh(plant, "flowerpot_plant", M.leaves), potPos);

    MeshData ball;
    addSphere(ball, {0.0f, 0.0f, 0.0f}, 0.3f, 40, 20, 1.0f);
    const glm::dvec3 ballRest(-1.8, 0.3, -1.0);
    const int ballNode = L.object("ball_red", L.mesh(ball, "ball_red", M.red), ballRest);
    // It bobs so that TAA and the reflections of moving things are tested with it (at rest at time 0).
    L.bob("ball_red_bob", ballNode, ballRest, 0.5, 2.0, 17);
}

void buildPuddles(Layout& L, const Materials& M) {
    struct Spec {
        const char* name;
        double x, z;
        glm::dvec3 tangent;
        double halfU, halfV, reflectance;
    };
    const Spec specs[] = {
        {"puddle_pot", -3.0, 0.6, {1, 0, 0}, 1.3, 1.1, 0.7},         // reflects flowerpot + brick pillar
        {"puddle_large", 2.8, 1.8, {0, 0, 1}, 2.5, 1.5, 0.75},       // long grazing reflections
        {"puddle_glass", 6.2, -5.2, {0.8, 0, 0.6}, 1.2, 0.6, 0.65},  // in front of the oblique glass
        {"puddle_mirror", 0.0, -7.4, {1, 0, 0}, 2.0, 0.8, 0.7},      // in front of the mirror wall
        {"puddle_stairs", -5.2, -2.0, {1, 0, 0}, 0.8, 0.5, 0.6},     // at the foot of the stairs
        {"puddle_small", -0.6, 4.6, {1, 0, 0}, 0.4, 0.3, 0.6},
        {"puddle_window", 11.0, -1.0, {1, 0, 0}, 0.42, 1.3, 0.7},    // behind the east glass, seen through it
    };
    uint32_t seed = 101;
    for (const Spec& s : specs) {
        const glm::dvec3 t(s.x, kPuddleY, s.z);
        MeshData m;
        addPuddle(m, glm::vec3(t), glm::vec3(s.tangent), static_cast<float>(s.halfU), static_cast<float>(s.halfV), 48, seed++);
        // The reflector is the tightest rectangle around the outline, exactly what the editor's
        // auto-fit finds for this mesh (engine/scene/reflector_fit.hpp), so authoring and auto-fit agree.
        std::vector<glm::vec3> triangles;
        for (uint32_t index : m.indices) triangles.push_back(m.positions[index]);
        const std::optional<ppr::scene::Reflector> fit = ppr::scene::fitReflector(triangles);
        if (!fit) throw std::logic_error(std::string("puddle ") + s.name + ": outline is not planar");
        ReflectorDesc r;
        r.center = glm::dvec3(fit->center) - t;  // node space
        r.normal = glm::dvec3(fit->normal);
        r.tangent = glm::dvec3(fit->tangent);
        r.halfExtents = glm::dvec2(fit->halfExtents);
        r.reflectance = s.reflectance;
        L.reflective(s.name, L.mesh(toNode(m, t), s.name, M.water), t, r);
    }
}

// Free-standing tinted glass panel in a dark frame; built in panel space (X tangent, Y up,
// Z normal) and rotated into node space, so the node itself keeps an identity rotation.
void glassPanel(Layout& L, const Materials& M, const std::string& name, const glm::dvec3& center,
                const glm::dvec3& tangent, const glm::dvec3& normal, float halfW, float halfH) {
    const glm::mat3 basis = panelBasis(tangent, normal);
    MeshData front, frame;  // one two-sided pane: the glass pass draws both sides
    addQuad(front, {-halfW, -halfH, 0.0f}, {2 * halfW, 0, 0}, {0, 2 * halfH, 0}, 1.0f);
    const float yBottom = -static_cast<float>(center.y), post = 0.08f;
    addBox(frame, {-halfW - post, yBottom, -0.05f}, {-halfW, halfH + 0.12f, 0.03f}, 1.0f, AllFaces & ~NegY);
    addBox(frame, {halfW, yBottom, -0.05f}, {halfW + post, halfH + 0.12f, 0.03f}, 1.0f, AllFaces & ~NegY);
    addBox(frame, {-halfW, yBottom, -0.05f}, {halfW, -halfH, 0.03f}, 1.0f, AllFaces & ~NegY);
    addBox(frame, {-halfW, halfH, -0.05f}, {halfW, halfH + 0.12f, 0.03f}, 1.0f);
    for (MeshData* m : {&front, &frame}) transformMesh(*m, basis, glm::vec3(0.0f));

    ReflectorDesc r;
    r.normal = normal;
    r.tangent = tangent;
    r.halfExtents = {halfW, halfH};
    r.glass = true;
    r.reflectance = 1.0;  // glass reflects by its Fresnel term alone
    L.reflective(name, L.mesh(front, name, M.glass), center, r);
    L.object(name + "_frame", L.mesh(frame, name + "_frame", M.frame), center);
}

void buildProps(Layout& L, const Materials& M) {
    // Two round pillars flanking the mirror and two in the open hall.
    const int pillar = L.mesh(roundPillar(3.4f), "pillar_round", M.sandstone);
    L.object("pillar_mirror_w", pillar, {-4.4, 0, -9.9});
    L.object("pillar_mirror_e", pillar, {4.4, 0, -9.9});
    L.object("pillar_hall_a", pillar, {0.2, 0, -4.6});
    L.object("pillar_hall_b", pillar, {5.4, 0, -1.4});

    // Coloured props, placed beyond the puddles as seen from the cameras.
    MeshData cube, tall, ball, bigBall;
    addBox(cube, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, 1.0f, AllFaces & ~NegY);
    addBox(tall, {-0.3f, 0.0f, -0.3f}, {0.3f, 1.8f, 0.3f}, 1.0f, AllFaces & ~NegY);
    addSphere(ball, {0.0f, 0.0f, 0.0f}, 0.45f, 40, 20, 1.0f);
    addSphere(bigBall, {0.0f, 0.0f, 0.0f}, 0.55f, 48, 24, 1.0f);
    const int cubeMesh = L.mesh(cube, "crate", M.yellow), tallMesh = L.mesh(tall, "column_block", M.green);
    L.object("crate_yellow", cubeMesh, {4.3, 0, -3.3}, 25.0);
    L.object("sphere_blue", L.mesh(bigBall, "sphere_blue", M.blue), {2.0, 0.55, -2.2});
    L.object("block_green", tallMesh, {1.6, 0, -8.7}, 15.0);
    L.object("sphere_orange", L.mesh(ball, "sphere_orange", M.orange), {-1.7, 0.45, -8.5});
    MeshData red;
    addBox(red, {-0.35f, 0.0f, -0.35f}, {0.35f, 0.7f, 0.35f}, 1.0f, AllFaces & ~NegY);
    L.object("crate_red", L.mesh(red, "crate_red", M.red), {-1.2, 0, 3.8}, -30.0);
    MeshData teal;  // beyond the puddle behind the east glass: what it reflects, seen through the glass
    addBox(teal, {-0.25f, 0.0f, -0.4f}, {0.25f, 0.8f, 0.4f}, 1.0f, AllFaces & ~NegY);
    L.object("crate_teal", L.mesh(teal, "crate_teal", M.teal), {11.72, 0, -1.0});
    MeshData white;
    addBox(white, {-0.6f, 0.0f, -0.3f}, {0.6f, 0.9f, 0.3f}, 1.0f, AllFaces & ~NegY);
    L.object("bench_white", L.mesh(white, "bench_white", M.white), {8.0, 0, -3.0}, 60.0);

    // Reflective surfaces PPR cannot take (curved, one of them rough): the screen-space fallback
    // shades them. A mirror ball between the large and the small puddles, a satin steel post by the
    // blue sphere.
    MeshData chromeBall, post;
    addSphere(chromeBall, {0.0f, 0.0f, 0.0f}, 0.5f, 64, 32, 1.0f);
    L.object("sphere_chrome", L.mesh(chromeBall, "sphere_chrome", M.chrome), {0.3, 0.5, 0.8});
    addCylinder(post, {0.0f, 0.0f, 0.0f}, 0.28f, 0.28f, 1.3f, 48, false, true, 1.0f);
    L.object("post_steel", L.mesh(post, "post_steel", M.satinSteel), {3.3, 0, -0.9});

    glassPanel(L, M, "glass_east", {10.5, 1.45, -1.0}, {0, 0, 1}, {-1, 0, 0}, 2.5f, 1.2f);
    glassPanel(L, M, "glass_oblique", {7.0, 1.45, -7.5}, {0.8, 0, 0.6}, {-0.6, 0, 0.8}, 1.8f, 1.2f);
}

// The south corner: three normal-mapped reflectors (rippled puddle, polished tiles with bevels and
// grout, a wavy old mirror) and props for them to reflect. Everything lies beyond z = 9.2, behind
// every other named camera, so their pictures do not change.
void buildNormalMapped(Layout& L, const Materials& M) {
    {
        const glm::dvec3 t(-3.5, kPuddleY, 10.5);
        MeshData tiles;
        addQuad(tiles, glm::vec3(t) + glm::vec3(-1.8f, 0.0f, 1.0f), {3.6f, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f}, 2.0f);
        ReflectorDesc r;
        r.normal = {0, 1, 0};
        r.tangent = {1, 0, 0};
        r.halfExtents = {1.8, 1.0};
        r.reflectance = 0.45;
        L.reflective("tiles_polished", L.mesh(toNode(tiles, t), "tiles_polished", M.tilesPolished), t, r);
    }
    {
        const glm::dvec3 t(0.6, kPuddleY, 10.3);
        MeshData m;
        addPuddle(m, glm::vec3(t), {1, 0, 0}, 1.2f, 0.75f, 48, 211);
        std::vector<glm::vec3> triangles;
        for (uint32_t index : m.indices) triangles.push_back(m.positions[index]);
        const std::optional<ppr::scene::Reflector> fit = ppr::scene::fitReflector(triangles);
        if (!fit) throw std::logic_error("puddle_rippled: outline is not planar");
        ReflectorDesc r;
        r.center = glm::dvec3(fit->center) - t;
        r.normal = glm::dvec3(fit->normal);
        r.tangent = glm::dvec3(fit->tangent);
        r.halfExtents = glm::dvec2(fit->halfExtents);
        r.reflectance = 0.7;
        L.reflective("puddle_rippled", L.mesh(toNode(m, t), "puddle_rippled", M.waterRippled), t, r);
    }
    {
        // 3.2 x 2 m, facing north (towards the camera), on a low plinth in a frame.
        const glm::dvec3 c(4.3, 1.4, 11.6);
        MeshData frame, glassMesh;
        addBox(frame, {2.5f, 0.0f, 11.62f}, {6.1f, 0.4f, 11.85f}, kStoneTex);
        addBox(frame, {2.5f, 2.4f, 11.62f}, {6.1f, 2.6f, 11.85f}, kStoneTex);
        addBox(frame, {2.5f, 0.4f, 11.62f}, {2.7f, 2.4f, 11.85f}, kStoneTex);
        addBox(frame, {5.9f, 0.4f, 11.62f}, {6.1f, 2.4f, 11.85f}, kStoneTex);
        L.object("mirror_wavy_frame", L.mesh(frame, "mirror_wavy_frame", M.frame), {0, 0, 0});
        addQuad(glassMesh, {1.6f, -1.0f, 0.0f}, {-3.2f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, 2.0f);
        ReflectorDesc r;
        r.normal = {0, 0, -1};
        r.tangent = {-1, 0, 0};
        r.halfExtents = {1.6, 1.0};
        r.reflectance = 0.9;
        L.reflective("mirror_wavy", L.mesh(glassMesh, "mirror_wavy", M.mirrorWavy), c, r);
    }
    // Props: behind the tiles and the puddle (reflected in them), in front of the mirror.
    L.object("pillar_south", L.mesh(roundPillar(2.6f), "pillar_south", M.sandstone), {-3.0, 0, 11.45});
    MeshData crate, ball, block;
    addBox(crate, {-0.35f, 0.0f, -0.35f}, {0.35f, 0.7f, 0.35f}, 1.0f, AllFaces & ~NegY);
    addSphere(ball, {0.0f, 0.0f, 0.0f}, 0.4f, 40, 20, 1.0f);
    addBox(block, {-0.25f, 0.0f, -0.25f}, {0.25f, 1.5f, 0.25f}, 1.0f, AllFaces & ~NegY);
    L.object("crate_south", L.mesh(crate, "crate_south", M.blue), {1.0, 0, 11.45}, 20.0);
    L.object("sphere_south", L.mesh(ball, "sphere_south", M.red), {-1.0, 0.4, 10.9});
    L.object("block_south", L.mesh(block, "block_south", M.yellow), {-5.0, 0, 11.5});
    L.object("block_south_b", L.mesh(block, "block_south_b", M.green), {2.4, 0, 9.7}, 30.0);
}

void buildCameras(Layout& L) {
    L.camera("overview", {8.0, 7.5, 9.0}, -37.2, -25.5);
    L.camera("puddles", {-2.7, 1.3, 3.4}, -2.0, -16.0);
    L.camera("grazing", {2.8, 0.4, 5.2}, 0.0, -6.0);
    L.camera("stairs", {-6.0, 2.7, 0.3}, -28.4, -21.0);
    L.camera("mirror", {-2.2, 1.7, -3.6}, 17.0, -5.0);
    L.camera("glass", {7.6, 2.3, 1.4}, 62.0, -24.0);  // through the east glass at the puddle behind it
    L.camera("normalmap", {0.4, 2.5, 5.4}, 180.0, -22.0);  // the normal-mapped reflectors of the south corner
}

}  // namespace

void writeDefaultScene(const std::string& dir) {
    GltfWriter w;
    const Materials M = createMaterials(w, dir);
    Layout L(w);
    buildWalls(L, M);
    buildMirror(L, M);
    buildStairs(L, M);
    buildFlowerpotCorner(L, M);
    buildPuddles(L, M);
    buildProps(L, M);
    buildNormalMapped(L, M);
    buildCameras(L);
    // Informative only: the renderer owns its light; this records the intended sun.
    w.setSceneExtras(Json{{"ppr_sun_direction_to_light", vec(glm::normalize(glm::dvec3(0.35, 0.85, 0.4)))}});
    w.write(dir, "default");

    // One reflector per line: compact, yet diffs name the reflector that changed.
    std::string text = "{\n  \"version\": 1,\n  \"reflectors\": [";
    for (size_t i = 0; i < L.worldReflectors.size(); ++i)
        text += (i ? ",\n    " : "\n    ") + reflectorJson(L.worldReflectors[i]).dump();
    text += "\n  ]\n}\n";
    const std::string path = dir + "/default.reflectors.json";
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error(path + ": cannot write");
}

}  // namespace gen
