#pragma once
// Mirror-camera math for the planar ground truth: the reflection about a reflector plane and an
// oblique near plane for the reverse-Z, infinite-far projection (camera.hpp), so the mirrored render
// keeps only what lies in front of the reflector.
#include "scene/reflector.hpp"

#include <glm/glm.hpp>

namespace ppr::scene {

// Reflection about the plane through `pointOnPlane` with unit `normal` (an involution: R·R = I).
glm::mat4 reflectionMatrix(const glm::vec3& normal, const glm::vec3& pointOnPlane);

// Replaces the depth row of a projection made by projectionMatrix() so that the near clip plane
// (depth = 1) becomes `viewPlane` (view space, xyz unit, kept where dot(xyz, p) + w >= 0). The far
// side stays unclipped inside the frustum (depth >= 0.5 there) and depth still decreases
// monotonically along every ray, so the usual GREATER depth test works. Lengyel's oblique frustum
// idea, adapted to reverse-Z with an infinite far plane.
glm::mat4 obliqueProjection(const glm::mat4& proj, const glm::vec4& viewPlane);

struct MirrorView {
    glm::mat4 view{1.0f};  // main view · reflection: renders the real world as seen in the mirror
    glm::mat4 proj{1.0f};  // oblique, clipped at the reflector plane (raised by `clipOffset`)
    glm::vec3 eye{0.0f};   // the mirrored camera position (for view-dependent shading)
};
// The view of `reflector`'s plane for a main camera. `clipOffset` (metres) lifts the clip plane off
// the reflector so the reflecting surface itself is not drawn into its own reflection.
MirrorView mirrorView(const glm::mat4& view, const glm::mat4& proj, const glm::vec3& eye, const Reflector& reflector,
                      float clipOffset = 2e-3f);

// Conservative: false only when the camera is not in front of the reflector's plane or the
// rectangle lies entirely outside one side of the frustum of `viewProj`.
bool reflectorMaybeVisible(const Reflector& reflector, const glm::mat4& viewProj, const glm::vec3& eye);

}  // namespace ppr::scene
