#pragma once
// A reflection technique as the trunk sees it. Each technique is a module in app/techniques/ that owns
// its passes and per-frame state and reads its own typed settings (TechniqueFrame::settings); the
// table in techniques/technique_table.cpp lists them once.
#include "frame/frame_services.hpp"

#include <optional>
#include <string>

namespace ppr::app {

class Technique {
public:
    virtual ~Technique() = default;
    // Adds the technique's passes; returns its reflection image (common/reflection.h), or none.
    virtual std::optional<graph::ImageHandle> addReflection(TechniqueFrame& frame) = 0;
    // Why it cannot render a frame of this size ("" when it can): the frame is drawn without reflections.
    virtual std::string unsupported(VkExtent2D) const { return {}; }
    // A warning to show while it renders (e.g. reflectors beyond PPR's budget).
    virtual std::string warning(const FrameServices&) const { return {}; }
    // As the reference beside another technique (A/B): the screen's reflection alone, no glass.
    virtual std::optional<graph::ImageHandle> addReference(TechniqueFrame&) { return std::nullopt; }
};

}  // namespace ppr::app
