#pragma once
// The scene's reflection probe (--set fallback_env=1 env_source=probe; docs/normalmaps.md): one cubemap
// of the lit scene, rendered the first time a frame asks for it, with the frame's G-buffer, lighting
// and shadow passes (passes/env_probe/) in a graph and a submit of its own, waited for — like the
// ray-traced reference's acceleration structures, once per renderer (per scene load); never per frame.
// Frames import the cube into their graph (bind), so the graph plans its barriers: the one-time render
// leaves it in the state its last write put it in, the next frame that samples it transitions it.
//
// It is not re-rendered when reflectors are edited (the lit scene it shows does not depend on them) or
// when settings change (shadowres is the first render's); the scene is static.
#include "common/environment.hpp"
#include "common/frame.h"
#include "env_probe/env_probe.h"
#include "env_probe/env_probe_pass.hpp"
#include "scene/probe_placement.hpp"
#include "vk/cube_image.hpp"

#include <optional>

namespace ppr::app {

class EnvironmentProbe {
public:
    EnvironmentProbe(const vk::Context& ctx, const gpu::GpuScene& scene, const passes::ShadowPass& shadow,
                     const passes::GBufferPass& gbuffer, const passes::LightingPass& lighting);
    ~EnvironmentProbe();
    EnvironmentProbe(const EnvironmentProbe&) = delete;
    EnvironmentProbe& operator=(const EnvironmentProbe&) = delete;

    // Renders the probe unless it already is: placed for `reflectors` (scene/probe_placement.hpp), lit as
    // `main` (this frame's constants: light, sky), drawn with `in`'s scene and reflector bindings.
    void prepare(const passes::FrameInputs& in, const gpu::FrameConstants& main, const std::vector<scene::Reflector>& reflectors,
                 uint32_t shadowRes);
    // Imports the cube into a frame's graph, for the passes that fall back to the environment. `probe`
    // is honoured only once prepare() has rendered it.
    passes::Environment bind(graph::RenderGraph& g, bool fallback, bool probe);

    struct Stats {
        scene::ProbePlacement placement;
        uint32_t faceSize = gpu::kEnvProbeFaceSize;
        double gpuMs = 0.0;   // the render's passes, from their timestamps
        double wallMs = 0.0;  // CPU wall time of prepare(): record, submit, wait
        uint64_t bytes = 0;   // the cube's device memory (the render's transients are freed after it)
    };
    uint32_t renders() const { return renders_; }  // 0 or 1: how many times the cube was rendered
    const std::optional<Stats>& stats() const { return stats_; }  // once rendered

private:
    const vk::Context& ctx_;
    const gpu::GpuScene& scene_;
    passes::EnvProbePass pass_;
    vk::CubeImage cube_;
    graph::ExternalImage sampled_;  // the cube view, imported by frames
    graph::ExternalImage layers_;   // the 2D-array view, imported by the one-time render
    vk::Buffer data_;               // gpu::EnvProbeData
    vk::Buffer faces_;              // gpu::FrameConstants per face
    uint32_t renders_ = 0;
    std::optional<Stats> stats_;
};

}  // namespace ppr::app
