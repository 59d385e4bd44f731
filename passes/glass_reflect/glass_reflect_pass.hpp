#pragma once
// PPR's reflection pass for the glass atlas (glass_reflect.comp): the atlas's encoded offsets → the
// glass reflection atlas (rgba16f) that the glass forward pass samples.
#include "common/frame_inputs.hpp"
#include "common/transfer_batch.hpp"
#include "graph/graph.hpp"

#include <optional>

namespace ppr::passes {

struct GlassReflectInputs {
    graph::ImageHandle atlas;      // r32ui, written by ppr.project
    graph::ImageHandle sceneColor;  // the lit scene
    graph::BufferHandle regions, regionList, blockStarts;  // glass_regions.hpp
    uint32_t regionCount = 0;
    uint32_t atlasSize = 0;        // texels per side
    uint32_t blockCount = 0;       // GlassRegionTable::blockCount: one workgroup each, over a region and a ring around it
    uint32_t flags = 0;            // ppr_reflect.h toggles (holes, filter, antibleed)
    // The reflection atlas cleared in a technique's batch (queueClears), for a reader of the whole
    // atlas (debug=atlas). Unset: add() writes the regions and a one-texel ring around each, all the
    // glass pass reads, and leaves the rest as it finds it (or, with no region, clears it in a pass of
    // its own, "ppr.glass.reflection.clear").
    std::optional<graph::ImageHandle> clearedTarget;
};

class GlassReflectPass {
public:
    static constexpr VkFormat kFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    explicit GlassReflectPass(const vk::Context& ctx);
    // Pass "ppr.glass.reflect"; returns the reflection atlas (same size as the atlas).
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const GlassReflectInputs& inputs) const;
    // Creates the reflection atlas (inputs.atlasSize) and queues its clear in `batch`:
    // inputs.clearedTarget after batch.add().
    static void queueClears(graph::RenderGraph& g, TransferBatch& batch, GlassReflectInputs& inputs);
    // The reflection atlas, "ppr.glass.reflection", uncleared.
    static graph::ImageHandle createTarget(graph::RenderGraph& g, uint32_t atlasSize);
    // --set debug=atlas: draws the reflection atlas over `color` (HDR), fitted to the screen height
    // (pass "glass.atlas_view"); returns the new version.
    graph::ImageHandle addAtlasView(graph::RenderGraph& g, const FrameInputs& in, graph::ImageHandle reflectionAtlas, graph::ImageHandle color) const;

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_, view_;
};

}  // namespace ppr::passes
