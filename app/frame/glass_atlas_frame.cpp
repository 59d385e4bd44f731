#include "frame/glass_atlas_frame.hpp"

#include "scene/camera.hpp"

#include <algorithm>
#include <cstdio>

namespace ppr::app {

VkExtent2D GlassStats::usedExtent() const {
    VkExtent2D used{};
    for (const scene::GlassRegion& r : layout) {
        used.width = std::max(used.width, static_cast<uint32_t>(r.atlasOrigin.x + r.atlasSize.x));
        used.height = std::max(used.height, static_cast<uint32_t>(r.atlasOrigin.y + r.atlasSize.y));
    }
    return used;
}

std::string GlassStats::overflowMessage() const {
    if (!overflowed()) return {};
    char scaleText[32];
    std::snprintf(scaleText, sizeof scaleText, "%.3g", scale);
    const std::string side = std::to_string(atlasSize);
    return "glass atlas " + side + "x" + side + " overflowed: " + std::to_string(scaled) + " of " + std::to_string(visible) +
           " visible glass panels' reflections scaled to " + scaleText + ", " + std::to_string(dropped) +
           " dropped (the farthest first); raise --set glass_atlas";
}

uint32_t GlassAtlasFrame::pack(uint32_t slot, const GlassSettings& settings, const ReflectorSet& reflectors, const glm::mat4& viewProj,
                               const glm::vec3& eye, VkExtent2D extent) {
    stats_[slot].reset();
    scene::GlassAtlasLayout layout;
    const bool glass = settings.enabled && !reflectors.glassIndices().empty();
    if (glass)
        layout = scene::packGlassAtlas(reflectors.list(), reflectors.glassIndices(), viewProj, eye, scene::kNearPlane,
                                       {extent.width, extent.height}, settings.atlas);
    table_.fill(layout);
    const uint32_t atlasSize = layout.regions.empty() ? 1u : settings.atlas;
    if (glass) {
        GlassStats stats;
        stats.atlasSize = settings.atlas;
        stats.visible = layout.visible;
        stats.scaled = layout.scaled;
        stats.dropped = layout.dropped;
        stats.scale = layout.scale;
        stats.layout = std::move(layout.regions);
        stats_[slot] = std::move(stats);
    }
    return atlasSize;
}

std::optional<GlassRegionsBound> GlassAtlasFrame::packAndUpload(graph::RenderGraph& g, uint32_t slot, const GlassSettings& settings,
                                                                 const ReflectorSet& reflectors, const glm::mat4& viewProj,
                                                                 const glm::vec3& eye, VkExtent2D extent) {
    pack(slot, settings, reflectors, viewProj, eye, extent);
    const std::optional<GlassStats>& s = stats_[slot];
    if (!s || s->regions() == 0) return std::nullopt;
    return GlassRegionsBound{upload(g), s->regions(), s->atlasSize, s->usedExtent()};
}

}  // namespace ppr::app
