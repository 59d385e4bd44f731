#pragma once
// One screen-space ray-marching technique (its shader includes ssr_common/ssr_pixel.glsl): the four
// SSR baselines each make one of these from their own folder, and PPR uses ssr-hiz's as its
// fallback on the non-planar tile list.
#include "common/environment.hpp"
#include "common/frame_inputs.hpp"
#include "gbuffer/gbuffer_pass.hpp"
#include "graph/graph.hpp"
#include "ssr_common/ssr.h"
#include "tile_classify/tile_classify_pass.hpp"

#include <optional>
#include <string>

namespace ppr::passes {

// The shared parameter block (--set ssr_*).
struct SsrParams {
    float maxDistance = 0.0f, thickness = 0.0f, thicknessScale = 0.0f;
    uint32_t maxSteps = 0;
    bool hizSkip = false;  // --set hiz_skip (ssr-hiz's march)
};

struct SsrInputs {
    const GBuffer* gbuffer = nullptr;
    graph::ImageHandle sceneColor;             // the lit scene the reflection samples
    VkBuffer reflectors = VK_NULL_HANDLE;      // ReflectorData[] (plane normals of reflector pixels)
    const TileLists* tiles = nullptr;          // tile classification of this frame
    std::optional<graph::ImageHandle> hiz;     // hiz/hiz_pass.hpp atlas (techniques that use it)
    uint32_t hizLevels = 0;
    SsrParams params;
    bool indirect = true;                      // over the tile lists (--set indirect) or the whole screen
    bool mappedNormals = false;                // reflector pixels use the normal-mapped normal (--set normalmap)
    Environment environment;                   // what misses show (--set fallback_env, env_source)
};

class SsrTracePass {
public:
    static constexpr VkFormat kReflectionFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    // `name` prefixes the pass names; usesHiz: the shader binds the depth hierarchy (binding 11).
    SsrTracePass(const vk::Context& ctx, shader::Spirv spirv, std::string name, bool usesHiz);

    // The technique on its own: a new reflection image (common/reflection.h) with every reflective
    // pixel shaded. Indirect: "<name>.clear", then "<name>.planar" and "<name>.other" over the two
    // tile lists; otherwise one whole-screen pass "<name>".
    // `distanceOut`: also a new reflected-path image (common/reflection.h: the path eye → surface → the
    // point seen at the hit, 0 = none, and that point's motion slot), for TAA's virtual point.
    graph::ImageHandle addTechnique(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs,
                                    graph::ImageHandle* distanceOut = nullptr) const;
    // Shades only reflective pixels that no reflector rectangle covers into `reflection` (read-write),
    // in a pass named `passName`: over the non-planar tile list, or the whole screen. `holes`: then
    // also the reflector pixels `reflection` holds no reflection for, in "<passName>.holes" (over the
    // planar list, or over `holeTiles` when given: PprReflectPass's list of the planar tiles that hold
    // such a pixel, at class 0). `distance`, when given, is the caller's path-length image: those
    // pixels' lengths are written into it (in/out).
    graph::ImageHandle addFallback(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs, graph::ImageHandle reflection,
                                   const std::string& passName, bool holes, graph::ImageHandle* distance = nullptr,
                                   const TileLists* holeTiles = nullptr) const;

private:
    // `distance`: the path-length image to write (updated to the pass's version), or none.
    graph::ImageHandle trace(graph::RenderGraph& g, const FrameInputs& in, const SsrInputs& inputs, graph::ImageHandle target,
                             const std::string& passName, uint32_t pixelClasses, std::optional<uint32_t> listClass, bool fresh,
                             graph::ImageHandle* distance, uint32_t flags = 0) const;
    const vk::Context& ctx_;
    std::string name_;
    bool usesHiz_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
