#pragma once
// TAA resolve (--set taa=1): the jittered HDR frame + the history image ("taa.color", a graph history
// resource) → the new history, which is the frame's anti-aliased HDR output (with taa_split=1, the
// history holds the surface part and the output is a separate image, "taa.frame"). The G-buffer's material
// target gives each pixel's motion slot (per-object motion of an animated scene's moving draws). With
// taa_average=1 each history has its frame counts beside it ("*.samples", taa_color.glsl blendHistory).
#include "common/frame_inputs.hpp"
#include "common/workgroup_widths.hpp"
#include "graph/history.hpp"

#include <optional>

namespace ppr::passes {

struct TaaReflectionInputs {
    graph::ImageHandle reflection;               // common/reflection.h
    std::optional<graph::ImageHandle> distance;  // reflected path lengths (x), when the technique gives them
    graph::ImageHandle depth, normal;            // G-buffer
    uint32_t mode = 0;                           // taa.h kReproject*
    bool average = true;                         // taa_average (taa.h kTaaStillSamples)
    bool stillSpread = true;                     // taa_still_spread (taa.h kTaaSpreadSigma)
    bool motionCap = false;                      // taa_reflection_cap (taa.h kTaaMotionCap)
    bool rimKeep = true;                         // taa_rim_keep (TaaReflectionPush::rimKeep)
    bool stillRange = true;                      // taa_still_range (TaaReflectionPush::stillRange)
    bool stillKeep = true;                       // taa_still_keep (TaaReflectionPush::stillKeep)
    bool movingEdge = true;                      // taa_moving_edge (TaaReflectionPush::movingEdge)
    uint32_t threads = 0;                        // taa_threads: invocations per tile (taa_threads.hpp); 0: the device's default
};

struct TaaInputs {
    graph::ImageHandle hdr;                     // the composited frame; alpha = its reflection weight
    graph::ImageHandle depth, material;         // G-buffer (material alpha: a moving draw's motion slot)
    // The technique's reflected-path image, when reflector pixels should also fetch their history
    // where their reflection was (reproject=virtual); without it, the surface's motion alone.
    std::optional<graph::ImageHandle> reflectedPath;
    // taa_split=1: the reflection as the composite blended it (taa.reflection's output). The history then
    // holds the surface part alone and the output adds the reflection back (taa_split.comp).
    std::optional<graph::ImageHandle> shownReflection;
    // With shownReflection and average: taa.reflection's new history, whose kept reflections give a
    // still pixel off a reflector's rim this frame (the jitter's doing) its own reflection.
    std::optional<graph::ImageHandle> reflectionHistory;
    bool average = true;  // taa_average (taa.h kTaaStillSamples)
    bool motionCap = true;  // taa_motion_cap (taa.h kTaaMotionCap)
    bool stillSpread = true;  // taa_still_spread (taa.h kTaaSpreadSigma)
    bool stillRange = true;   // taa_still_range (TaaPush::stillRange)
    bool movingFilter = true;  // taa_moving_filter (TaaPush::movingFilter)
    uint32_t threads = 0;     // taa_threads: invocations per tile (taa_threads.hpp); 0: the device's default
};

struct TaaReflectionOutput {
    graph::ImageHandle shown;    // for the composite (the technique's class codes in alpha)
    graph::ImageHandle history;  // the new history (alpha: the virtual point's depth)
};

class TaaPass {
public:
    static constexpr const char* kHistoryName = "taa.color";
    static constexpr const char* kReflectionHistoryName = "taa.reflection";
    // How many frames each history pixel holds, beside each history (taa_average).
    static constexpr const char* kSamplesName = "taa.color.samples";
    static constexpr const char* kReflectionSamplesName = "taa.reflection.samples";
    // A still run's luma range or moments, beside each (taa_average; read with taa_still_spread).
    static constexpr const char* kSpreadName = "taa.color.spread";
    static constexpr const char* kReflectionSpreadName = "taa.reflection.spread";
    static constexpr const char* kHistoryNames[] = {kHistoryName,         kReflectionHistoryName, kSamplesName,
                                                    kReflectionSamplesName, kSpreadName,            kReflectionSpreadName};
    static constexpr VkFormat kHistoryFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kSamplesFormat = VK_FORMAT_R16G16_SFLOAT;

    explicit TaaPass(const vk::Context& ctx);
    // taa_threads=auto: the invocations per tile the device gets (taa.h kTaaThreads, kTaaThreadsGpu).
    static uint32_t autoThreads(const vk::DeviceInfo& device);
    // Returns the frame's anti-aliased HDR output (the new history itself, unless split).
    graph::ImageHandle add(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history, const TaaInputs& inputs) const;
    // The reflection's own history (taa_reflection*.comp): the accumulated reflection image for the
    // composite (same class codes in alpha as the technique's) and the new history.
    TaaReflectionOutput addReflection(graph::RenderGraph& g, const FrameInputs& in, graph::HistoryStore& history,
                                     const TaaReflectionInputs& inputs) const;

private:
    const vk::Context& ctx_;
    WidthPipelines pipelines_[2][2];        // [split][average]: taa.comp, taa_average.comp, taa_split*.comp
    WidthPipelines reflectionPipelines_[2];  // [average]
};

}  // namespace ppr::passes
