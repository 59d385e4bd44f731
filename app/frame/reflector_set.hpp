#pragma once
// The reflectors of the scene as every frame uses them: the list, its GPU copies per frame in flight
// (rewritten only when the list changes), the surfaces bound to each, the glass panes among those PPR
// projects, and the warning when the list exceeds PPR's budget.
#include "common/reflector_buffer.hpp"
#include "common/surface_binding.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ppr::app {

class ReflectorSet {
public:
    ReflectorSet(const vk::Context& ctx, const scene::Scene& scene, uint32_t framesInFlight);

    void set(std::vector<scene::Reflector> reflectors);
    // Makes `slot`'s GPU copies current (after the slot's fence).
    void update(uint32_t slot);

    const std::vector<scene::Reflector>& list() const { return list_; }
    uint64_t version() const { return version_; }
    const passes::ReflectorBuffer& buffer() const { return *buffer_; }
    const passes::SurfaceBindingBuffer& surfaces() const { return *surfaces_; }
    const std::vector<uint32_t>& glassIndices() const { return glassIndices_; }  // glass panes PPR projects
    const std::string& budgetWarning() const { return budgetWarning_; }           // "" within kPprMaxReflectors

private:
    const scene::Scene& scene_;
    std::unique_ptr<passes::ReflectorBuffer> buffer_;
    std::unique_ptr<passes::SurfaceBindingBuffer> surfaces_;
    std::vector<scene::Reflector> list_;
    uint64_t version_ = 0;
    std::vector<uint32_t> glassIndices_;
    std::string budgetWarning_;
};

}  // namespace ppr::app
