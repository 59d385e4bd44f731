#pragma once
// glTF node animation (translation, rotation, scale channels; STEP, LINEAR and CUBICSPLINE samplers):
// what moves, and where it is at a given time. The loader fills Scene::animation; the renderer asks
// it for the moving draws' world matrices once per frame and uploads only those.
//
// All channels of all glTF animations play together on one clock and loop over the longest one,
// which is what a sample viewer shows. A scene without animations has an empty SceneAnimation and
// costs nothing per frame.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ppr::scene {

struct AnimationChannel {
    enum class Path : uint8_t { Translation, Rotation, Scale };
    enum class Interpolation : uint8_t { Step, Linear, CubicSpline };
    uint32_t node = 0;  // into SceneAnimation::nodes
    Path path = Path::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // seconds, finite, >= 0, strictly increasing, at least one
    std::vector<glm::vec4> values;  // one per key (CUBICSPLINE: in-tangent, value, out-tangent per key);
                                    // translation/scale in xyz, rotation as a quaternion x, y, z, w
};

// A node on the way from a root to a moving draw, with its rest pose (the node's own TRS).
struct AnimatedNode {
    int parent = -1;              // into SceneAnimation::nodes, -1 = its parent does not move
    glm::mat4 staticParent{1.0f}; // parent == -1: the (still) world matrix of the glTF parent
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit length
    glm::vec3 scale{1.0f};
    // A still node given by a glTF `matrix` (below a moving one): its local matrix, used instead of
    // the TRS above. Never set on a node a channel targets (glTF forbids animating such nodes).
    std::optional<glm::mat4> matrix;
    std::string name;             // for messages
};

struct SceneAnimation {
    std::vector<AnimatedNode> nodes;        // parents before children
    std::vector<AnimationChannel> channels;
    std::vector<uint32_t> draws;            // Scene::draws indices that move, ascending
    std::vector<uint32_t> drawNode;         // per entry of `draws`: its node in `nodes`
    float duration = 0.0f;                  // seconds: the last key of any channel; the clock loops

    bool empty() const { return draws.empty(); }
    // World matrix of each moving draw at `seconds` (wrapped into [0, duration]), in `draws` order.
    // `worlds` is resized to draws.size() (no allocation once it has that size). Not reentrant: it
    // works in the scratch below, so one thread at a time per SceneAnimation.
    void evaluate(double seconds, std::vector<glm::mat4>& worlds) const;

    // evaluate()'s scratch, kept so that a warmed-up call allocates nothing.
    struct Pose {
        glm::vec3 translation;
        glm::quat rotation;
        glm::vec3 scale;
    };
    mutable std::vector<Pose> scratchPose;
    mutable std::vector<glm::mat4> scratchWorld;
};

}  // namespace ppr::scene
