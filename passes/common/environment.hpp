#pragma once
// What a pass that falls back to the environment (--set fallback_env) binds for common/environment.glsl:
// the reflection probe's placement and cube, and which of sky and probe to show. Made once per frame by
// TechniqueFrame::environment() (app/frame/environment_probe.hpp).
#include "graph/graph.hpp"

namespace ppr::passes {

struct Environment {
    bool fallback = false;                 // misses show the environment (--set fallback_env=1)
    bool probe = false;                    // ... and it is the probe (env_source=probe); false: the sky
    VkBuffer probeData = VK_NULL_HANDLE;   // EnvProbeData (env_probe/env_probe.h), host-written uniform
    graph::ImageHandle probeCube;          // sampled as a cube; bound always, read only when `probe`
};

}  // namespace ppr::passes
