#pragma once
// The frame constants uniform buffer: per frame in flight, the main view (view 0) and, when a
// technique asks for them (planar, A/B against it), one mirrored view per visible plane group.
// Host-written, outside the graph; sized once per reflector change, never per frame.
#include "common/frame.h"
#include "common/frame_inputs.hpp"
#include "frame/reflector_set.hpp"
#include "planar/planar_pass.hpp"
#include "scene/camera.hpp"
#include "settings/frame_settings.hpp"

#include <optional>
#include <vector>

namespace ppr::app {

class FrameConstantsBuffer {
public:
    FrameConstantsBuffer(const vk::Context& ctx, const shader::Samplers& samplers, const passes::ImageClear& clear, const gpu::GpuScene& scene,
                         uint32_t framesInFlight);
    ~FrameConstantsBuffer();
    FrameConstantsBuffer(const FrameConstantsBuffer&) = delete;
    FrameConstantsBuffer& operator=(const FrameConstantsBuffer&) = delete;

    // Room for the main view and one mirrored view per reflector (waits for the device when it grows).
    void reserveViews(uint32_t views);
    // Writes `slot`'s main view; starts the frame (mirrored views are written on first request).
    // `jitterPixels` moves the projection by a sub-pixel offset (TAA; zero leaves it untouched).
    void beginFrame(uint32_t slot, const scene::CameraPose& camera, VkExtent2D extent, const ViewSettings& view,
                    const glm::mat4& lightViewProj, glm::vec2 jitterPixels);
    const gpu::FrameConstants& main() const { return main_; }
    passes::FrameInputs inputs(const ReflectorSet& reflectors, uint32_t view = 0) const;
    // One mirrored view per plane group with a visible reflector, in group order (written once a frame).
    const std::vector<passes::PlanarView>& mirroredViews(const ReflectorSet& reflectors);

private:
    void write(uint32_t view, const gpu::FrameConstants& f);
    void flush();
    const vk::Context& ctx_;
    const shader::Samplers& samplers_;
    const passes::ImageClear& clear_;
    bool computeClear_ = false;  // this frame's clear method (ViewSettings::clear, auto resolved)
    bool depthPrepass_ = false;  // this frame's: ViewSettings::depthPrepass, auto resolved
    uint64_t opaqueTriangles_ = 0;  // what the pre-pass would draw (depth_prepass=auto)
    const gpu::GpuScene& scene_;
    uint32_t framesInFlight_;
    vk::Buffer buffer_;
    VkDeviceSize stride_ = 0;
    uint32_t capacity_ = 0;
    uint32_t frameIndex_ = 0;
    uint32_t slot_ = 0;
    VkExtent2D extent_{};
    glm::vec3 eye_{};
    gpu::FrameConstants main_{};
    std::optional<glm::mat4> prevViewProj_;  // last frame's, unjittered (none before the first frame)
    std::optional<std::vector<passes::PlanarView>> mirrored_;  // this frame's, once requested
};

}  // namespace ppr::app
