#pragma once
// PPR reflection pass (ppr_reflect.comp): intermediate buffer + lit scene → reflection image.
#include "common/environment.hpp"
#include "common/frame_inputs.hpp"
#include "common/transfer_batch.hpp"
#include "graph/graph.hpp"

#include <optional>
#include "tile_classify/tile_classify_pass.hpp"

namespace ppr::passes {

struct PprReflectInputs {
    graph::ImageHandle intermediate;
    graph::ImageHandle sceneColor;
    graph::ImageHandle reflectorIds;
    graph::ImageHandle depth, normal;         // G-buffer (normal maps, the environment's reflected ray)
    graph::ImageHandle material;              // G-buffer: the reflected points' motion slots (kPprWriteDistance)
    VkBuffer reflectors = VK_NULL_HANDLE;     // ReflectorData[] (plane normals)
    graph::BufferHandle tileSurvivors;  // ppr.project's per-tile counts (debug=tiles)
    const TileLists* tiles = nullptr;
    uint32_t flags = 0;           // ppr_reflect.h kPpr* toggles; kPprIndirect dispatches over the planar tiles
    uint32_t debugView = 0;       // frame.h kDebug* (intermediate, holes and tiles draw here)
    uint32_t maxReflectorId = 0;  // ids above this get no reflection (beyond PPR's budget)
    Environment environment;      // what holes show with kPprEnvironment (the probe adds kPprEnvironmentProbe)
    // kPprWriteDistance: the reflected-path image (common/reflection.h, screen-sized, cleared to 0 by
    // add()) that receives each reflector pixel's path length and motion slot; add() returns it
    // written in `distanceOut`.
    std::optional<graph::ImageHandle> distance;
    // With kPprIndirect: list the planar tiles holding a pixel ppr.fallback.holes will march
    // (kPprListMappedHoles); add() returns the list in `mappedHolesOut`.
    bool listMappedHoles = false;
    graph::BufferHandle stats;  // PprFrameStats (with the list: tilesWithMappedHoles copied in)
    // The mapped holes' list state, cleared in a technique's batch (PprReflectPass::queueClears);
    // unset: add() clears it in a pass of its own, "ppr.holes.clear".
    std::optional<graph::BufferHandle> clearedHoles;
};

class PprReflectPass {
public:
    static constexpr VkFormat kReflectionFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    explicit PprReflectPass(const vk::Context& ctx);
    // Whole-screen debug views ignore kPprIndirect.
    // mappedHolesOut (with listMappedHoles and an indirect dispatch): the tiles as a one-class
    // TileLists (arguments and list at class 0), for SsrTracePass::addFallback; untouched otherwise.
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, const PprReflectInputs& inputs,
                           graph::ImageHandle* distanceOut = nullptr, std::optional<TileLists>* mappedHolesOut = nullptr) const;
    // Queues in `batch` the clear of the mapped holes' list state add() would make for these inputs on
    // an `extent` screen, if any: inputs.clearedHoles after batch.add().
    static void queueClears(graph::RenderGraph& g, TransferBatch& batch, VkExtent2D extent, PprReflectInputs& inputs);

private:
    const vk::Context& ctx_;
    shader::Pipeline pipeline_;
};

}  // namespace ppr::passes
