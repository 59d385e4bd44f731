// bindDrawsToReflectors: node-extras bindings kept, then name match, then the geometric rule.
#include "scene/scene.hpp"

#include "test_util.hpp"

#include <glm/gtc/matrix_transform.hpp>

using namespace ppr::scene;

namespace {
Vertex vert(glm::vec3 p) { return Vertex{p, {0, 1, 0}, glm::vec4(1, 0, 0, 1), {0, 0}}; }
}  // namespace

TEST(BindDraws, NamePrecedenceAndGeometry) {
    Scene s;
    s.vertices = {vert({-1, 0, -1}), vert({1, 0, -1}), vert({1, 0, 1}), vert({-1, 0, 1})};
    s.indices = {0, 3, 2, 0, 2, 1};
    s.meshes.push_back(Mesh{"quad", 0, 6, 0, 0, {-1, 0, -1}, {1, 0, 1}});
    s.materials.push_back(Material{.name = "mirror", .reflective = true});
    Reflector floor;
    floor.name = "floor";
    floor.halfExtents = {4, 4};
    Reflector named;
    named.name = "Named";
    named.center = {0, 50, 0};
    s.reflectors = {floor, named};
    auto draw = [](glm::vec3 at, float scale, std::string name) {
        DrawItem d;
        d.world = glm::scale(glm::translate(glm::mat4(1), at), glm::vec3(scale));
        d.nodeName = std::move(name);
        return d;
    };
    s.draws = {draw({0, 0.005f, 0}, 1, "inside"),      // within tolerance of the plane, inside
               draw({3.5f, 0, 0}, 1, "overhang"),      // x up to 4.5 > 4 + 0.01
               draw({0, 0.5f, 0}, 1, "above"),         // off the plane
               draw({0, 0, 0}, 1, "Named"),            // name match wins over geometry
               draw({0, 0, 0}, 1, "preset")};
    s.draws[4].reflector = 1;  // node extras binding is kept
    bindDrawsToReflectors(s);
    EXPECT_EQ(s.draws[0].reflector, 0);
    EXPECT_EQ(s.draws[1].reflector, -1);
    EXPECT_EQ(s.draws[2].reflector, -1);
    EXPECT_EQ(s.draws[3].reflector, 1);
    EXPECT_EQ(s.draws[4].reflector, 1);

    // Non-reflective material: geometry alone does not bind.
    s.materials[0].reflective = false;
    s.draws[0].reflector = -1;
    bindDrawsToReflectors(s);
    EXPECT_EQ(s.draws[0].reflector, -1);
}
