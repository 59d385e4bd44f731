#pragma once
// What the trunk and the techniques publish on a frame's blackboard (graph::Blackboard), one struct
// per meaning. Taps (readbacks, pick, A/B, overlay) find what they read here.
#include "common/environment.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "glass_forward/glass_forward_pass.hpp"
#include "graph/blackboard.hpp"
#include "hiz/hiz_pass.hpp"

namespace ppr::app {

struct LitColor {  // lighting output (HDR), what every technique reflects
    graph::ImageHandle image;
};
struct ShadowMap {
    graph::ImageHandle image;
};
struct TechniqueReflection {  // the technique's reflection image (common/reflection.h), when it has one
    graph::ImageHandle image;
};
struct ReflectedPath {  // planar only: per pixel, the reflected path length and its classes (planar/planar.h)
    graph::ImageHandle image;
};
// Per pixel the length of the reflected path, eye → reflector → reflected point (metres; 0 = unknown),
// R32F or the x of planar's RG32F: TAA's reflection history finds the virtual point with it.
struct ReflectionDistance {
    graph::ImageHandle image;
};
struct ShownReflection {  // what the composite blends: the technique's, or A/B's split of it
    graph::ImageHandle image;
};
struct DepthHierarchy {  // when the frame built one (ssr-hiz, PPR's fallback)
    passes::HizAtlas atlas;
};
struct DepthHierarchyTiles {  // PPR's reach pass stored the hierarchy's levels of every tile (HizPass::add's fineLevels)
    graph::ImageHandle atlas;
};
struct EnvironmentBound {  // when a technique falls back to the environment (TechniqueFrame::environment)
    passes::Environment environment;
};
struct HdrColor {  // composited scene with glass, before tonemapping
    graph::ImageHandle image;
};
struct FinalColor {  // tonemapped output (the target), before and after overlays
    graph::ImageHandle image;
};
// Also published: passes::GBuffer, passes::GlassReflection (when a technique resolved glass).

}  // namespace ppr::app
