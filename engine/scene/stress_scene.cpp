// The `stress:N` scene: N mirror tiles plus fixed, deterministic content for them to reflect.
#include "scene/stress_scene.hpp"

#include "scene/errors.hpp"
#include "scene/tangents.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <stdexcept>

namespace ppr::scene {

std::optional<uint32_t> parseStressSpec(const std::string& spec) {
    const std::string prefix = "stress:";
    if (spec.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    const std::string digits = spec.substr(prefix.size());
    // Digits only (no sign, blanks or suffix); the length cap keeps the accumulation from overflowing.
    bool ok = !digits.empty() && digits.size() <= 9;
    uint32_t n = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') ok = false;
        else n = n * 10 + uint32_t(c - '0');
    }
    if (!ok || n < 1 || n > kStressMaxTiles)
        detail::fail("--scene " + spec + ": expected stress:N with N a whole number in 1.." +  // one line, whatever spec holds
                     std::to_string(kStressMaxTiles));
    return n;
}

namespace {

struct MeshBuilder {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;

    uint32_t vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
        vertices.push_back({p, n, glm::vec4(0.0f), uv});
        return uint32_t(vertices.size() - 1);
    }
    // Orders the triangle counter-clockwise seen from where its vertex normals point (glTF front
    // face), so the shape helpers need not get every winding right by hand; drops degenerate ones.
    void triangle(uint32_t a, uint32_t b, uint32_t c) {
        const glm::vec3 face = glm::cross(vertices[b].position - vertices[a].position, vertices[c].position - vertices[a].position);
        if (glm::length(face) < 1e-9f) return;
        const glm::vec3 n = vertices[a].normal + vertices[b].normal + vertices[c].normal;
        if (glm::dot(face, n) < 0.0f) std::swap(b, c);
        indices.insert(indices.end(), {a, b, c});
    }
    // Rectangle origin + s·u + t·v, facing cross(u, v); UVs in metres.
    void quad(const glm::vec3& origin, const glm::vec3& u, const glm::vec3& v) {
        const glm::vec3 n = glm::normalize(glm::cross(u, v));
        const float lu = glm::length(u), lv = glm::length(v);
        const uint32_t a = vertex(origin, n, {0, 0}), b = vertex(origin + u, n, {lu, 0});
        const uint32_t c = vertex(origin + u + v, n, {lu, lv}), d = vertex(origin + v, n, {0, lv});
        triangle(a, b, c);
        triangle(a, c, d);
    }
    void box(const glm::vec3& lo, const glm::vec3& hi) {
        const glm::vec3 d = hi - lo;
        const glm::vec3 X{d.x, 0, 0}, Y{0, d.y, 0}, Z{0, 0, d.z};
        quad({hi.x, lo.y, hi.z}, -Z, Y);  // +X
        quad(lo, Z, Y);                   // -X
        quad({lo.x, hi.y, lo.z}, Z, X);   // +Y
        quad(lo, X, Z);                   // -Y
        quad({lo.x, lo.y, hi.z}, X, Y);   // +Z
        quad({hi.x, lo.y, lo.z}, -X, Y);  // -Z
    }
    // Vertical cylinder on `base` with a top cap (the bottom stands on the floor, never seen).
    void cylinder(const glm::vec3& base, float radius, float height, int segments) {
        const uint32_t first = uint32_t(vertices.size());
        for (int i = 0; i <= segments; ++i) {
            const float a = glm::two_pi<float>() * float(i) / float(segments);
            const glm::vec3 n{std::sin(a), 0, std::cos(a)};
            const float s = a * radius;
            vertex(base + n * radius, n, {s, 0});
            vertex(base + n * radius + glm::vec3(0, height, 0), n, {s, height});
        }
        for (int i = 0; i < segments; ++i) {
            const uint32_t k = first + 2 * uint32_t(i);
            triangle(k, k + 2, k + 3);
            triangle(k, k + 3, k + 1);
        }
        const glm::vec3 top = base + glm::vec3(0, height, 0), up{0, 1, 0};
        const uint32_t centre = vertex(top, up, {0, 0});
        for (int i = 0; i < segments; ++i) {
            const float a0 = glm::two_pi<float>() * float(i) / float(segments);
            const float a1 = glm::two_pi<float>() * float(i + 1) / float(segments);
            const glm::vec3 p0 = top + radius * glm::vec3(std::sin(a0), 0, std::cos(a0));
            const glm::vec3 p1 = top + radius * glm::vec3(std::sin(a1), 0, std::cos(a1));
            triangle(centre, vertex(p0, up, {p0.x, p0.z}), vertex(p1, up, {p1.x, p1.z}));
        }
    }
    void sphere(const glm::vec3& centre, float radius, int segments, int rings) {
        const uint32_t first = uint32_t(vertices.size());
        for (int r = 0; r <= rings; ++r) {
            const float theta = glm::pi<float>() * float(r) / float(rings);  // from the north pole
            for (int s = 0; s <= segments; ++s) {
                const float phi = glm::two_pi<float>() * float(s) / float(segments);
                const glm::vec3 n{std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
                vertex(centre + n * radius, n, {phi * radius, theta * radius});
            }
        }
        const uint32_t row = uint32_t(segments) + 1;
        for (int r = 0; r < rings; ++r)
            for (int s = 0; s < segments; ++s) {
                const uint32_t k = first + uint32_t(r) * row + uint32_t(s);
                triangle(k, k + row, k + row + 1);  // pole triangles collapse and are dropped
                triangle(k, k + row + 1, k + 1);
            }
    }
};

// Deterministic pseudo-random numbers (Numerical Recipes LCG): the scene must be identical run to run.
struct Lcg {
    uint32_t state;
    float next() {  // 0..1
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    }
};

struct Builder {
    Scene& s;
    int material(const std::string& name, const glm::vec3& colour, float roughness, bool reflective = false) {
        Material m;
        m.name = name;
        m.baseColorFactor = glm::vec4(colour, 1.0f);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = roughness;
        m.reflective = reflective;  // textures stay -1: the GPU scene then uses the factors alone
        s.materials.push_back(m);
        return int(s.materials.size() - 1);
    }
    uint32_t mesh(const std::string& name, MeshBuilder&& b, int material) {
        detail::generateTangents(b.vertices, b.indices);  // the loader's convention for the w sign
        Mesh m;
        m.name = name;
        m.firstIndex = uint32_t(s.indices.size());
        m.indexCount = uint32_t(b.indices.size());
        m.vertexOffset = int32_t(s.vertices.size());
        m.material = material;
        m.boundsMin = m.boundsMax = b.vertices.front().position;
        for (const Vertex& v : b.vertices) {
            m.boundsMin = glm::min(m.boundsMin, v.position);
            m.boundsMax = glm::max(m.boundsMax, v.position);
        }
        s.vertices.insert(s.vertices.end(), b.vertices.begin(), b.vertices.end());
        s.indices.insert(s.indices.end(), b.indices.begin(), b.indices.end());
        s.meshes.push_back(m);
        return uint32_t(s.meshes.size() - 1);
    }
    // Content meshes are built in world space: one draw with an identity matrix.
    void draw(const std::string& name, MeshBuilder&& b, int material) {
        s.draws.push_back({mesh(name, std::move(b), material), glm::mat4(1.0f), name, -1});
    }
    void camera(const std::string& name, const glm::vec3& position, const glm::vec3& target) {
        CameraPose p;
        p.position = position;
        yawPitchFromDirection(target - position, p.yawDeg, p.pitchDeg);
        s.cameras.push_back({name, p});
    }
};

// N tiles over the floor square. Cells are cols x rows with cols = ceil(sqrt N); a partial last row
// stretches its cells to the full width, so the tiled area is the same for every N (otherwise N = 3
// would cover 3/4 of what N = 4 covers and the sweep would measure geometry, not reflector count).
void addTiles(Builder& b, uint32_t n) {
    uint32_t cols = 1;
    while (cols * cols < n) ++cols;
    const uint32_t rows = (n + cols - 1) / cols;
    const float half = kStressFloorSize * 0.5f, cellZ = kStressFloorSize / float(rows);

    // One unit quad (x, z in -0.5..0.5, facing +Y) shared by all tiles; each draw scales it. The
    // normal matrix (inverse transpose) and the bind test (world-space vertices) handle the scale.
    MeshBuilder quad;
    quad.quad({-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 0, -1});  // u along +X, the reflector tangent
    const int tileMaterial = b.material("tile", {0.04f, 0.045f, 0.05f}, 0.05f, true);
    const uint32_t tileMesh = b.mesh("tile", std::move(quad), tileMaterial);

    for (uint32_t i = 0; i < n; ++i) {
        const uint32_t row = i / cols, col = i % cols;
        const uint32_t inRow = row + 1 == rows ? n - row * cols : cols;
        const float cellX = kStressFloorSize / float(inRow);
        const glm::vec3 centre{-half + (float(col) + 0.5f) * cellX, kStressTileHeight, -half + (float(row) + 0.5f) * cellZ};
        const glm::vec2 size = kStressTileFill * glm::vec2(cellX, cellZ);

        Reflector r;
        r.name = "tile_" + std::to_string(i);
        r.center = centre;
        r.normal = {0, 1, 0};
        r.tangent = {1, 0, 0};
        r.halfExtents = size * 0.5f;
        r.kind = ReflectorKind::Opaque;
        r.reflectance = 0.85f;
        b.s.reflectors.push_back(r);

        const glm::mat4 world = glm::scale(glm::translate(glm::mat4(1.0f), centre), {size.x, 1.0f, size.y});
        b.s.draws.push_back({tileMesh, world, r.name, int(i)});
    }
}

// Grout, walls, a ring of pillars and props on the tiles. Props keep out of the south-east quarter
// (x, z > 0) so that reflective_100 sees nothing but floor there.
void addContent(Builder& b) {
    MeshBuilder grout;
    grout.quad({-10, 0, 10}, {20, 0, 0}, {0, 0, -20});
    b.draw("grout", std::move(grout), b.material("grout", {0.12f, 0.12f, 0.12f}, 0.9f));

    MeshBuilder north, west;
    north.box({-10.3f, 0, -10.3f}, {10.3f, 6.0f, -10.0f});
    west.box({-10.3f, 0, -10.0f}, {-10.0f, 5.0f, 10.3f});
    b.draw("wall_north", std::move(north), b.material("wall_north", {0.75f, 0.70f, 0.60f}, 0.8f));
    b.draw("wall_west", std::move(west), b.material("wall_west", {0.45f, 0.55f, 0.70f}, 0.6f));
    MeshBuilder band, panels;  // markings, so a reflected wall is recognisable as such
    band.box({-10.0f, 2.2f, -10.0f}, {10.0f, 2.6f, -9.95f});
    for (int k = 0; k < 4; ++k) panels.box({-10.0f, 0.6f, -7.0f + 4.5f * float(k)}, {-9.95f, 2.4f, -5.8f + 4.5f * float(k)});
    b.draw("wall_band", std::move(band), b.material("band", {0.8f, 0.15f, 0.1f}, 0.5f));
    b.draw("wall_panels", std::move(panels), b.material("panels", {0.95f, 0.8f, 0.2f}, 0.4f));

    const glm::vec3 palette[] = {{0.85f, 0.2f, 0.15f}, {0.95f, 0.55f, 0.1f}, {0.9f, 0.85f, 0.2f}, {0.25f, 0.7f, 0.3f},
                                 {0.15f, 0.65f, 0.7f}, {0.2f, 0.35f, 0.85f}, {0.6f, 0.3f, 0.75f}, {0.9f, 0.9f, 0.88f}};
    int colours[8];
    for (int k = 0; k < 8; ++k) colours[k] = b.material("colour_" + std::to_string(k), palette[k], 0.15f + 0.1f * float(k));

    Lcg rng{20240611u};
    // Ring: 12 pillars, 3 per side of the 18 m square, between the tiles and the grout edge.
    for (int k = 0; k < 12; ++k) {
        const int side = k / 3, step = k % 3;
        const float t = -6.0f + 6.0f * float(step);  // corners stay free for the overview camera
        const glm::vec2 xz = side == 0 ? glm::vec2(t, -9) : side == 1 ? glm::vec2(9, t) : side == 2 ? glm::vec2(-t, 9) : glm::vec2(-9, -t);
        const float height = 2.0f + 3.0f * rng.next();
        MeshBuilder p;
        if (k % 2 == 0) p.box({xz.x - 0.4f, 0, xz.y - 0.4f}, {xz.x + 0.4f, height, xz.y + 0.4f});
        else p.cylinder({xz.x, 0, xz.y}, 0.4f, height, 24);
        b.draw("pillar_" + std::to_string(k), std::move(p), colours[int(rng.next() * 8.0f) % 8]);
    }
    // Props standing on the tiles (y = tile height), spheres and boxes alternating.
    const glm::vec2 spots[8] = {{-5.0f, -5.0f}, {-1.5f, -5.5f}, {2.5f, -3.0f}, {5.0f, -6.0f},
                                {-2.5f, 2.0f},  {-6.0f, 5.0f},  {-4.5f, -1.0f}, {1.0f, -1.2f}};
    for (int k = 0; k < 8; ++k) {
        const float size = 0.5f + 0.6f * rng.next();
        const glm::vec3 base{spots[k].x, kStressTileHeight, spots[k].y};
        MeshBuilder p;
        if (k % 2 == 0) p.sphere(base + glm::vec3(0, size, 0), size, 32, 16);
        else p.box(base - glm::vec3(size * 0.7f, 0, size * 0.7f), base + glm::vec3(size * 0.7f, 2.0f * size + 0.5f, size * 0.7f));
        b.draw("prop_" + std::to_string(k), std::move(p), colours[k]);
    }
}

void computeBounds(Scene& s) {
    bool any = false;
    for (const DrawItem& d : s.draws) {
        const Mesh& m = s.meshes[d.mesh];
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local{(corner & 1) ? m.boundsMax.x : m.boundsMin.x, (corner & 2) ? m.boundsMax.y : m.boundsMin.y,
                                  (corner & 4) ? m.boundsMax.z : m.boundsMin.z};
            const glm::vec3 p = glm::vec3(d.world * glm::vec4(local, 1.0f));
            s.boundsMin = any ? glm::min(s.boundsMin, p) : p;
            s.boundsMax = any ? glm::max(s.boundsMax, p) : p;
            any = true;
        }
    }
}

}  // namespace

Scene makeStressScene(uint32_t tileCount) {
    if (tileCount < 1 || tileCount > kStressMaxTiles)
        throw std::runtime_error("stress scene: " + std::to_string(tileCount) + " tiles: expected 1.." + std::to_string(kStressMaxTiles));
    Scene s;
    s.sourcePath = "stress:" + std::to_string(tileCount);
    Builder b{s};
    addTiles(b, tileCount);
    addContent(b);
    computeBounds(s);

    // Share of the image on mirror tiles (grout lines excluded), stress:64 at 320x180: rendered
    // (pixels whose debug=reflectors colour differs from debug=none, technique none) / CPU ray cast
    // (the unit test's helper, 128x72 rays). reflective_100 sees only tiles and grout (15 % of
    // the tiled square is grout at any N > 1; N = 1 gives 100 %).
    //   overview 0.104 / 0.105, reflective_5 0.050 / 0.054, reflective_25 0.253 / 0.254,
    //   reflective_100 0.851 / 0.853
    b.camera("overview", {13.0f, 12.0f, 13.0f}, {0.0f, 0.0f, 0.0f});
    b.camera("reflective_5", {0.0f, 1.7f, -2.0f}, {0.0f, 3.1f, -10.0f});       // north wall, tiles along the bottom
    b.camera("reflective_25", {7.5f, 2.5f, 8.0f}, {-3.0f, 2.3f, -8.0f});       // across the floor at the props
    b.camera("reflective_100", {4.0f, 2.6f, 5.3f}, {4.0f, 0.0f, 4.1f});        // down at the clear south-east quarter
    return s;
}

}  // namespace ppr::scene
