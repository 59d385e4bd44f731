// SceneAnimation::evaluate: samples every channel at one time (glTF 2.0 spec, "Animations" and
// Appendix C "Interpolation") and walks the moving nodes' hierarchy into the draws' world matrices.
#include "scene/animation.hpp"

#include <algorithm>
#include <cmath>

namespace ppr::scene {

namespace {

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }  // stored x, y, z, w

// A zero-length result (a spline through opposite keys can pass the origin) keeps `fallback`.
glm::quat normalizedOr(const glm::quat& q, const glm::quat& fallback) {
    const float len = glm::length(q);
    return len > 1e-12f && std::isfinite(len) ? q / len : fallback;
}

// The channel's value at `t`: clamped to the first and last keys outside their range. Rotations
// come back unnormalised (a spline leaves the unit sphere); the caller normalises.
glm::vec4 sample(const AnimationChannel& c, float t) {
    const size_t n = c.times.size();
    const bool cubic = c.interpolation == AnimationChannel::Interpolation::CubicSpline;
    auto value = [&](size_t k) { return c.values[cubic ? 3 * k + 1 : k]; };
    if (t <= c.times.front()) return value(0);
    if (t >= c.times.back()) return value(n - 1);
    const size_t k1 = size_t(std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin());
    const size_t k0 = k1 - 1;
    const float dt = c.times[k1] - c.times[k0];
    const float u = (t - c.times[k0]) / dt;
    switch (c.interpolation) {
    case AnimationChannel::Interpolation::Step: return value(k0);
    case AnimationChannel::Interpolation::Linear: {
        if (c.path != AnimationChannel::Path::Rotation) return glm::mix(value(k0), value(k1), u);
        // glm::slerp with three arguments takes the shorter arc (negates one end when dot < 0).
        const glm::quat q = glm::slerp(glm::normalize(toQuat(value(k0))), glm::normalize(toQuat(value(k1))), u);
        return {q.x, q.y, q.z, q.w};
    }
    case AnimationChannel::Interpolation::CubicSpline: {
        // Hermite: value_k, out-tangent of k0 and in-tangent of k1, tangents scaled by the key interval.
        const float u2 = u * u, u3 = u2 * u;
        return (2 * u3 - 3 * u2 + 1) * value(k0) + dt * (u3 - 2 * u2 + u) * c.values[3 * k0 + 2] +
               (-2 * u3 + 3 * u2) * value(k1) + dt * (u3 - u2) * c.values[3 * k1];
    }
    }
    return value(k0);
}

glm::mat4 trs(const SceneAnimation::Pose& p) {
    glm::mat4 m = glm::mat4_cast(p.rotation);
    m[0] *= p.scale.x;
    m[1] *= p.scale.y;
    m[2] *= p.scale.z;
    m[3] = glm::vec4(p.translation, 1.0f);
    return m;
}

}  // namespace

void SceneAnimation::evaluate(double seconds, std::vector<glm::mat4>& worlds) const {
    worlds.resize(draws.size());
    if (draws.empty()) return;
    double wrapped = duration > 0.0f && std::isfinite(seconds) ? std::fmod(seconds, double(duration)) : 0.0;
    if (wrapped < 0.0) wrapped += duration;  // fmod keeps the sign of a negative clock
    const float t = float(wrapped);

    scratchPose.resize(nodes.size());
    scratchWorld.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) scratchPose[i] = {nodes[i].translation, nodes[i].rotation, nodes[i].scale};
    for (const AnimationChannel& c : channels) {
        const glm::vec4 v = sample(c, t);
        Pose& p = scratchPose[c.node];
        switch (c.path) {
        case AnimationChannel::Path::Translation: p.translation = glm::vec3(v); break;
        case AnimationChannel::Path::Rotation: p.rotation = normalizedOr(toQuat(v), nodes[c.node].rotation); break;
        case AnimationChannel::Path::Scale: p.scale = glm::vec3(v); break;
        }
    }
    for (size_t i = 0; i < nodes.size(); ++i) {
        const AnimatedNode& n = nodes[i];
        const glm::mat4 local = n.matrix ? *n.matrix : trs(scratchPose[i]);
        scratchWorld[i] = (n.parent < 0 ? n.staticParent : scratchWorld[size_t(n.parent)]) * local;
    }
    for (size_t d = 0; d < draws.size(); ++d) worlds[d] = scratchWorld[drawNode[d]];
}

}  // namespace ppr::scene
