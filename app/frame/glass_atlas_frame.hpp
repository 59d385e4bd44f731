#pragma once
// This frame's glass atlas, shared by the techniques that reflect in glass (PPR and the planar
// reference pack the same layout): the CPU packing, the region table's upload and the counters that
// report.json ("glass") and the viewer show.
#include "frame/reflector_set.hpp"
#include "glass_reflect/glass_regions.hpp"
#include "scene/glass_atlas.hpp"
#include "settings/frame_settings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ppr::app {

// What the glass atlas held in a frame (report.json "glass", the viewer).
struct GlassStats {
    uint32_t atlasSize = 0;  // texels per side (--set glass_atlas)
    uint32_t visible = 0;    // glass panels on screen
    uint32_t scaled = 0;     // regions scaled down to fit (overflow)
    uint32_t dropped = 0;    // panels without a region (overflow: the farthest first)
    float scale = 1.0f;      // the common scale of the regions
    std::vector<scene::GlassRegion> layout;  // where each panel's region lies (screen and atlas)
    uint32_t regions() const { return static_cast<uint32_t>(layout.size()); }  // panels with a region
    // The atlas columns and rows holding regions, from its top-left corner: what the glass passes
    // dispatch over (the rest keeps the clear).
    VkExtent2D usedExtent() const;
    bool overflowed() const { return scaled > 0 || dropped > 0; }
    // One line saying how the atlas overflowed ("" when it did not).
    std::string overflowMessage() const;
};

// A packed frame's regions as the glass passes bind them, the table uploaded.
struct GlassRegionsBound {
    passes::GlassRegionBuffers buffers;
    uint32_t count = 0, atlasSize = 0;
    VkExtent2D used{};  // GlassStats::usedExtent
};

class GlassAtlasFrame {
public:
    explicit GlassAtlasFrame(uint32_t framesInFlight) : stats_(framesInFlight) {}

    void reserve(uint32_t reflectors) { table_.reserve(reflectors); }  // once per reflector change
    void beginFrame(uint32_t slot) { stats_[slot].reset(); }
    // Packs the frame's atlas (stats(slot) is set when glass is on and panes exist); returns the atlas
    // size to allocate (1 without a region: bound but unused).
    uint32_t pack(uint32_t slot, const GlassSettings& settings, const ReflectorSet& reflectors, const glm::mat4& viewProj,
                  const glm::vec3& eye, VkExtent2D extent);
    // The region table's upload pass; its buffers are read by every glass consumer of the frame.
    passes::GlassRegionBuffers upload(graph::RenderGraph& g) const { return table_.add(g); }
    // The same upload queued in a technique's batch of transfers: `uploaded` after batch.add().
    void queueUpload(graph::RenderGraph& g, passes::TransferBatch& batch, passes::GlassRegionBuffers* uploaded) const {
        table_.queue(g, batch, uploaded);
    }
    // pack, then (when a pane got a region) upload: what a reference technique needs to resolve glass.
    std::optional<GlassRegionsBound> packAndUpload(graph::RenderGraph& g, uint32_t slot, const GlassSettings& settings,
                                                   const ReflectorSet& reflectors, const glm::mat4& viewProj, const glm::vec3& eye,
                                                   VkExtent2D extent);
    const std::optional<GlassStats>& stats(uint32_t slot) const { return stats_[slot]; }
    // The last packed frame's resolve workgroups (GlassRegionTable::blockCount).
    uint32_t resolveBlocks() const { return table_.blockCount(); }

private:
    passes::GlassRegionTable table_;
    std::vector<std::optional<GlassStats>> stats_;
};

}  // namespace ppr::app
