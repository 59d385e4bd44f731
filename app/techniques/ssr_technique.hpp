#pragma once
// The screen-space ray-marched baselines (ssr-brute, ssr-lowq, ssr-hiz, ssr-linear): classify tiles →
// [depth hierarchy] → march, one module for the four since they differ only in their pass. Reads
// SsrSettings and TileSettings.
#include "frame/technique.hpp"
#include "ssr_common/ssr_trace_pass.hpp"

#include <memory>

namespace ppr::app {

// The shared ray set-up of this frame (used by PPR's fallback too).
passes::SsrInputs ssrInputs(TechniqueFrame& frame, const passes::TileLists& tiles);

class SsrTechnique final : public Technique {
public:
    using MakePass = std::unique_ptr<passes::SsrTracePass> (*)(const vk::Context&);
    SsrTechnique(FrameServices& services, MakePass makePass, bool usesHierarchy)
        : pass_(makePass(services.ctx)), usesHierarchy_(usesHierarchy) {}
    std::optional<graph::ImageHandle> addReflection(TechniqueFrame& frame) override;

private:
    std::unique_ptr<passes::SsrTracePass> pass_;
    bool usesHierarchy_;
};

}  // namespace ppr::app
