#pragma once
// Reflector fitting (pure CPU logic): "reflector authoring could be automated". Turns planar
// triangle sets into reflector rectangles — the tightest (minimum-area) rectangle enclosing the
// triangles in their plane — for a whole scene's reflective draws or for the planar region under a
// cursor.
#include "scene/reflector.hpp"
#include "scene/scene.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace ppr::scene {

// Fits a reflector to a triangle soup (3 world-space vertices per triangle).
// - Plane: normal from the area-weighted triangle normals (triangles wound against the largest one
//   are flipped for the direction, so two-sided input still finds its plane), oriented along the
//   raw area-weighted winding normal (ties: the largest triangle's facing); through the
//   area-weighted centroid.
// - Refused (nullopt) when: the input is empty or not a multiple of 3 vertices, has a non-finite
//   coordinate, the total area is ~0 (<= 1e-6 · bounding-box diagonal², e.g. collinear points), any
//   vertex lies farther than `planeTolerance` from the plane (curved or bent geometry), or the
//   rectangle would be thinner than kMinHalfExtent.
// - Rectangle: all vertices projected into the plane; convex hull (Andrew's monotone chain), then
//   rotating calipers over the hull edges give the minimum-area enclosing rectangle (an optimal one
//   always has a side along a hull edge). The centre is the rectangle centre on the plane.
// - Tangent: along the rectangle's longer side (halfExtents.x >= halfExtents.y); sign canonical
//   (its largest-magnitude component positive, first such axis on ties). Near-squares (sides equal
//   within 1e-6 relative) take the lexicographically larger canonical axis (x, then y, then z).
// - name empty (so not yet valid for validateReflector, which wants a name), kind Opaque,
//   reflectance 1: callers override.
std::optional<Reflector> fitReflector(const std::vector<glm::vec3>& worldTriangleVertices, float planeTolerance = 1e-3f);

// The draw's mesh triangles in world space, 3 vertices per triangle. Empty when the draw's mesh or
// its index/vertex ranges are out of bounds.
std::vector<glm::vec3> worldTriangles(const Scene& scene, const DrawItem& draw);

// "The planar region under the cursor". Candidates: every draw's triangles whose three vertices lie
// within `planeTolerance` of the plane through `point` with `normal` and whose winding faces the
// same way (dot > 0). The seed is the candidate nearest to `point` (the one under it, else the
// nearest in that plane); the region is the seed's connected component, triangles being connected
// when they share a vertex position (within kRegionWeldDistance). The region is fitted with
// fitReflector at 2·planeTolerance (its vertices are within planeTolerance of the query plane,
// so within twice that of their own fitted plane). nullopt when no candidate or the fit refuses.
constexpr float kRegionWeldDistance = 1e-4f;  // metres
std::optional<Reflector> fitPlanarRegion(const Scene& scene, const glm::vec3& point, const glm::vec3& normal,
                                         float planeTolerance = 1e-3f);

// One reflector per draw whose material is reflective and whose triangles fit a plane (curved
// surfaces are skipped: the fit refuses them), in the scene's draw order. Named after the draw's
// node name (unnamed nodes: the mesh name, else "draw_<index>"); kind Glass for transparent
// materials (glTF alphaMode BLEND), else Opaque; reflectance 1.
std::vector<Reflector> autoFitAll(const Scene& scene, float planeTolerance = 1e-3f);

}  // namespace ppr::scene
