#pragma once
// `ppr fit` over a whole scene (pure CPU logic): split the selected materials' triangles into flat
// connected regions and fit each region's tightest rectangle (scene/reflector_fit.hpp). Unlike
// autoFitAll (one reflector per reflective draw), a region may span draws and a draw may hold many
// regions: a level exported as one mesh gets one reflector per floor, table top and window.
#include "scene/reflector.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace ppr::scene {

struct PlanarRegionOptions {
    std::vector<bool> materials;  // per Scene::materials index: selected (missing = not selected)
    float minArea = 0.05f;        // m² of triangles: smaller regions are dropped
    float planeTolerance = 1e-3f; // metres: how far a neighbour's vertices may lie off a triangle's plane
};

struct FittedRegion {
    Reflector reflector;        // named after the region's largest draw (node, else mesh, else material)
    int material = -1;          // the region's material (regions never mix materials)
    uint32_t triangles = 0;
    double area = 0.0;          // m² of the region's triangles
    double rectangleArea = 0.0; // m² of the fitted rectangle (area / rectangleArea: how much it fills)
    double maxPlaneDistance = 0.0;  // metres: the region's farthest vertex from the fitted plane
    bool wholeDraw = false;         // the region holds every selected triangle of the draw it is named after
};

struct PlanarRegionResult {
    std::vector<FittedRegion> regions;  // largest area first
    uint32_t droppedSmall = 0;          // regions under minArea
    uint32_t refused = 0;               // regions the rectangle fit refused (not flat within 2 × tolerance)
};

// Triangles are connected when they share a vertex position (within kRegionWeldDistance), have the
// same material and each lies within planeTolerance of the other's plane (either facing: a two-sided
// pane is one region). Each region is fitted with fitReflector at 2 × planeTolerance; kind Glass for
// transparent materials. Names are unique: the draw's name for a region that is the whole draw,
// numbered ("slab_1", "slab_2", ...) for regions that are parts of one.
PlanarRegionResult fitPlanarRegions(const Scene& scene, const PlanarRegionOptions& options);

}  // namespace ppr::scene
