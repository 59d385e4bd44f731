// glTF animations → Scene::animation. Every channel is validated (a broken one is an error even if
// it moves nothing visible); then only what moves a draw is kept: the targeted nodes with draws
// below them and the chains from the topmost animated ancestor down to those draws.
#include "scene/errors.hpp"
#include "scene/gltf_internal.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace ppr::scene::detail {

namespace {

using Path = AnimationChannel::Path;
using Interpolation = AnimationChannel::Interpolation;

struct ParsedChannel {
    int node = -1;  // glTF node
    AnimationChannel channel;
};

// One channel of one animation, read into an AnimationChannel whose node is still the glTF one.
struct ChannelReader {
    const GltfFile& file;
    const tinygltf::Animation& animation;
    const tinygltf::AnimationChannel& in;
    std::string label;  // "animation 'walk' channel 2", the accessors' `what` prefix
    size_t& totalValues;

    [[noreturn]] void bad(const std::string& field, const std::string& problem) const {
        fail(file.name + ": " + label + ": " + field + ": " + problem);
    }

    // False for a channel glTF says to ignore (no target node) or that the renderer does not use.
    bool read(ParsedChannel& out, bool& warnedWeights) const {
        const auto& nodes = file.model.nodes;
        if (in.sampler < 0 || size_t(in.sampler) >= animation.samplers.size())
            bad("sampler", std::to_string(in.sampler) + " out of range (" + std::to_string(animation.samplers.size()) + " samplers)");
        if (in.target_node == -1) return false;  // spec: a channel without target.node is ignored
        if (in.target_node < 0 || size_t(in.target_node) >= nodes.size())
            bad("target.node", std::to_string(in.target_node) + " out of range (" + std::to_string(nodes.size()) + " nodes)");
        AnimationChannel& c = out.channel;
        if (in.target_path == "translation") c.path = Path::Translation;
        else if (in.target_path == "rotation") c.path = Path::Rotation;
        else if (in.target_path == "scale") c.path = Path::Scale;
        else if (in.target_path == "weights") {
            if (!warnedWeights)
                std::cerr << file.name << ": " << label << ": target.path: 'weights' (morph targets) is not supported; ignored\n";
            warnedWeights = true;
            return false;
        } else {
            bad("target.path", "'" + in.target_path + "' unknown (translation, rotation, scale or weights)");
        }
        if (!nodes[size_t(in.target_node)].matrix.empty())
            bad("target.node", nodeLabel(file, in.target_node) + " has a matrix (glTF forbids animating it)");
        out.node = in.target_node;
        readSampler(animation.samplers[size_t(in.sampler)], "sampler " + std::to_string(in.sampler), c);
        return true;
    }

    void readSampler(const tinygltf::AnimationSampler& s, const std::string& field, AnimationChannel& c) const {
        if (s.interpolation == "STEP") c.interpolation = Interpolation::Step;
        else if (s.interpolation == "LINEAR") c.interpolation = Interpolation::Linear;
        else if (s.interpolation == "CUBICSPLINE") c.interpolation = Interpolation::CubicSpline;
        else bad(field + " interpolation", "'" + s.interpolation + "' unknown (STEP, LINEAR or CUBICSPLINE)");

        const AccessorView times = viewAccessor(file, s.input, AccessorKind::ScalarFloat, label + ": " + field + " input");
        if (times.count == 0) bad(field + " input", "no keys");
        const size_t perKey = c.interpolation == Interpolation::CubicSpline ? 3 : 1;
        const bool rotation = c.path == Path::Rotation;
        const AccessorView values = viewAccessor(file, s.output, rotation ? AccessorKind::Rotation : AccessorKind::Vec3Float,
                                                 label + ": " + field + " output");
        if (values.count != times.count * perKey)
            bad(field + " output", "count " + std::to_string(values.count) + ", expected " + std::to_string(times.count * perKey) +
                                       (perKey == 3 ? " (in-tangent, value, out-tangent per input time)" : " (one per input time)"));
        // Many channels may share one large accessor: the copies together are capped too.
        totalValues += values.count;
        if (totalValues > kMaxElements)
            bad(field + " output", "more than " + std::to_string(kMaxElements) + " animation values in the file");

        c.times.resize(times.count);
        for (size_t k = 0; k < times.count; ++k) {
            readFloats(times, k, &c.times[k]);
            const float t = c.times[k];
            if (!std::isfinite(t) || t < 0.0f) bad(field + " input", "time " + std::to_string(k) + " (" + fmtNum(t) + ") is not finite and >= 0");
            if (k > 0 && !(t > c.times[k - 1]))
                bad(field + " input", "time " + std::to_string(k) + " (" + fmtNum(t) + ") is not after the previous (" + fmtNum(c.times[k - 1]) + ")");
        }
        c.values.resize(values.count);
        for (size_t k = 0; k < values.count; ++k) {
            float v[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            readFloats(values, k, v);
            for (float f : v)
                if (!std::isfinite(f)) bad(field + " output", "value " + std::to_string(k) + " is not finite");
            c.values[k] = {v[0], v[1], v[2], v[3]};
            const bool tangent = perKey == 3 && k % 3 != 1;  // a spline's tangents may well be zero
            if (rotation && !tangent && !(glm::length(c.values[k]) > 1e-6f))
                bad(field + " output", "value " + std::to_string(k) + " is a zero quaternion");
        }
    }
};

std::string animationLabel(const tinygltf::Animation& a, size_t index) {
    return a.name.empty() ? "animation " + std::to_string(index) : "animation '" + a.name + "'";
}

// The node's rest pose as loaded (localMatrix in gltf_loader.cpp has checked its numbers).
AnimatedNode restNode(const GltfFile& file, int index) {
    const tinygltf::Node& n = file.model.nodes[size_t(index)];
    AnimatedNode out;
    out.name = n.name.empty() ? "node " + std::to_string(index) : n.name;
    if (n.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = float(n.matrix[size_t(i)]);  // both column-major
        out.matrix = m;
        return out;
    }
    if (n.translation.size() == 3) out.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
    if (n.rotation.size() == 4)
        out.rotation = glm::normalize(glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2])));
    if (n.scale.size() == 3) out.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
    return out;
}

}  // namespace

void loadAnimations(const GltfFile& file, const NodeTree& tree, Scene& scene) {
    const auto& model = file.model;
    std::vector<ParsedChannel> parsed;
    size_t totalValues = 0;
    bool warnedWeights = false;
    for (size_t a = 0; a < model.animations.size(); ++a) {
        const tinygltf::Animation& anim = model.animations[a];
        for (size_t k = 0; k < anim.channels.size(); ++k) {
            const ChannelReader reader{file, anim, anim.channels[k], animationLabel(anim, a) + " channel " + std::to_string(k), totalValues};
            ParsedChannel p;
            if (reader.read(p, warnedWeights)) parsed.push_back(std::move(p));
        }
    }
    if (parsed.empty()) return;

    // Per node, the topmost targeted node on its way up (itself included), -1 if none; tree.order
    // has parents first, so one pass suffices.
    const size_t nodeCount = model.nodes.size();
    std::vector<char> targeted(nodeCount, 0);
    for (const ParsedChannel& p : parsed) targeted[size_t(p.node)] = 1;
    std::vector<int> top(nodeCount, -1);
    for (int n : tree.order) {
        const int parent = tree.parent[size_t(n)];
        top[size_t(n)] = parent >= 0 && top[size_t(parent)] >= 0 ? top[size_t(parent)] : targeted[size_t(n)] ? n : -1;
    }
    // The moving nodes: each moving draw's chain up to its topmost animated ancestor.
    std::vector<char> moving(nodeCount, 0);
    for (int node : tree.drawNode) {
        if (top[size_t(node)] < 0) continue;
        for (int n = node; !moving[size_t(n)]; n = tree.parent[size_t(n)]) {
            moving[size_t(n)] = 1;
            if (n == top[size_t(node)]) break;
        }
    }

    SceneAnimation& out = scene.animation;
    std::vector<int> animatedIndex(nodeCount, -1);
    for (int n : tree.order) {
        if (!moving[size_t(n)]) continue;
        AnimatedNode node = restNode(file, n);
        const int parent = tree.parent[size_t(n)];
        if (parent >= 0 && moving[size_t(parent)]) node.parent = animatedIndex[size_t(parent)];
        else if (parent >= 0) node.staticParent = tree.world[size_t(parent)];
        animatedIndex[size_t(n)] = int(out.nodes.size());
        out.nodes.push_back(std::move(node));
    }
    for (size_t d = 0; d < tree.drawNode.size(); ++d) {
        const int node = tree.drawNode[d];
        if (top[size_t(node)] < 0) continue;
        out.draws.push_back(uint32_t(d));
        out.drawNode.push_back(uint32_t(animatedIndex[size_t(node)]));
    }
    for (ParsedChannel& p : parsed) {
        if (!moving[size_t(p.node)]) continue;  // nothing drawn below it
        p.channel.node = uint32_t(animatedIndex[size_t(p.node)]);
        out.duration = std::max(out.duration, p.channel.times.back());
        out.channels.push_back(std::move(p.channel));
    }
}

}  // namespace ppr::scene::detail
