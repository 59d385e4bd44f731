#pragma once
// Pixel-projected reflections: empty lists → classify tiles → bounds → [reach] → clear → project
// (per-tile culling, glass atlas) → [glass resolve] → reflect (indirect over reflector tiles) →
// [ssr-hiz fallback on the non-planar tiles]. Reads PprSettings, TileSettings, SsrSettings (fallback) and GlassSettings.
#include "common/transfer_batch.hpp"
#include "frame/technique.hpp"
#include "glass_reflect/glass_reflect_pass.hpp"
#include "ppr_bounds/ppr_bounds_pass.hpp"
#include "ppr_project/ppr_project_pass.hpp"
#include "ppr_reach/ppr_reach_pass.hpp"
#include "ppr_reflect/ppr_reflect_pass.hpp"
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::app {

class PprTechnique final : public Technique {
public:
    explicit PprTechnique(FrameServices& services);
    std::optional<graph::ImageHandle> addReflection(TechniqueFrame& frame) override;
    std::string unsupported(VkExtent2D extent) const override;
    std::string warning(const FrameServices& services) const override;

private:
    // Packs the frame's glass atlas and queues the region table's upload in `lists`, the atlas's clear
    // and (with a region) the resolve's target in `clears`; fills what it can of `project` and `resolve`.
    void queueGlass(TechniqueFrame& f, passes::TransferBatch& lists, passes::TransferBatch& clears, passes::PprProjectInputs& project,
                    passes::GlassRegionBuffers& regions, passes::GlassReflectInputs& resolve) const;
    passes::PprProjectPass project_;
    passes::PprReflectPass reflect_;
    passes::PprBoundsPass bounds_;
    passes::PprReachPass reach_;
    std::unique_ptr<passes::SsrTracePass> fallback_;  // ssr-hiz's pass, over the non-planar tiles
    std::string deviceWarning_;  // a driver known to project wrongly as configured (util/driver_defects.hpp)
};

}  // namespace ppr::app
