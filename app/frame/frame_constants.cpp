#include "frame/frame_constants.hpp"

#include "common/clear_pass.hpp"
#include "frame/depth_prepass.hpp"
#include "scene/mirror.hpp"

#include <cstring>

namespace ppr::app {

FrameConstantsBuffer::FrameConstantsBuffer(const vk::Context& ctx, const shader::Samplers& samplers, const passes::ImageClear& clear,
                                           const gpu::GpuScene& scene, uint32_t framesInFlight)
    : ctx_(ctx), samplers_(samplers), clear_(clear), scene_(scene), framesInFlight_(framesInFlight) {
    const VkDeviceSize align = 256;  // ≥ minUniformBufferOffsetAlignment on every known device
    stride_ = (sizeof(gpu::FrameConstants) + align - 1) / align * align;
    const scene::Scene& s = scene.cpu();
    for (uint32_t i = 0; i < s.draws.size(); ++i)
        if (!scene.transparent(i) && !scene.masked(i)) opaqueTriangles_ += s.meshes[s.draws[i].mesh].indexCount / 3;
}

FrameConstantsBuffer::~FrameConstantsBuffer() { vk::destroyBuffer(ctx_, buffer_); }

void FrameConstantsBuffer::reserveViews(uint32_t views) {
    if (views <= capacity_) return;
    vkDeviceWaitIdle(ctx_.device());  // frames in flight read the old buffer; a reflector change is rare
    vk::destroyBuffer(ctx_, buffer_);
    buffer_ = vk::createBuffer(ctx_, stride_ * views * framesInFlight_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload,
                               "frame constants");
    capacity_ = views;
}

void FrameConstantsBuffer::beginFrame(uint32_t slot, const scene::CameraPose& camera, VkExtent2D extent, const ViewSettings& view,
                                      const glm::mat4& lightViewProj, glm::vec2 jitterPixels) {
    slot_ = slot;
    extent_ = extent;
    computeClear_ = view.clear == ClearMethod::Compute ||
                    (view.clear == ClearMethod::Auto && passes::ImageClear::computeIsCheaper(ctx_.info()));
    depthPrepass_ = depthPrepassWanted(view.depthPrepass, opaqueTriangles_, uint64_t(extent.width) * extent.height);
    eye_ = camera.position;
    mirrored_.reset();
    gpu::FrameConstants f{};
    const float aspect = static_cast<float>(extent.width) / static_cast<float>(extent.height);
    f.view = scene::viewMatrix(camera);
    const glm::mat4 unjittered = scene::projectionMatrix(camera.fovYDeg, aspect, scene::kNearPlane);
    const glm::vec2 screen(extent.width, extent.height);
    // Only a non-zero jitter touches the matrix: with TAA off the frame stays bit-identical.
    f.proj = jitterPixels == glm::vec2(0.0f) ? unjittered : scene::jitteredProjection(unjittered, jitterPixels, screen);
    f.viewProj = f.proj * f.view;
    const glm::mat4 viewProjUnjittered = unjittered * f.view;
    f.prevViewProj = prevViewProj_.value_or(viewProjUnjittered);
    prevViewProj_ = viewProjUnjittered;
    f.jitter = glm::vec4(2.0f * jitterPixels / screen, 0.0f, 0.0f);
    f.invViewProj = glm::inverse(f.viewProj);
    const glm::vec3 lightDir = glm::normalize(glm::vec3(-0.45f, -0.8f, -0.4f));
    f.lightViewProj = lightViewProj;
    f.cameraPos = glm::vec4(camera.position, scene::kNearPlane);
    f.lightDir = glm::vec4(lightDir, 1.0f / static_cast<float>(view.shadowRes));
    f.lightColor = glm::vec4(3.2f, 3.0f, 2.7f, view.exposure);
    f.skyColor = glm::vec4(0.50f, 0.62f, 0.85f, 0.9f);
    f.groundColor = glm::vec4(0.22f, 0.20f, 0.18f, 0.0f);
    f.screenSize = glm::vec2(extent.width, extent.height);
    f.invScreenSize = 1.0f / f.screenSize;
    f.frameIndex = frameIndex_++;
    f.debugView = view.debug;
    main_ = f;
    write(0, f);
    flush();
}

passes::FrameInputs FrameConstantsBuffer::inputs(const ReflectorSet& reflectors, uint32_t view) const {
    passes::FrameInputs in;
    in.frameConstants = buffer_.buffer;
    in.frameConstantsOffset = (VkDeviceSize(slot_) * capacity_ + view) * stride_;
    in.frameConstantsSize = sizeof(gpu::FrameConstants);
    in.samplers = &samplers_;
    in.clear = &clear_;
    in.computeClear = computeClear_;
    in.depthPrepass = depthPrepass_;
    in.scene = &scene_;
    in.draws = scene_.drawBuffer(slot_);
    in.motion = scene_.motionBuffer(slot_);
    in.extent = extent_;
    in.drawReflectors = reflectors.surfaces().drawReflectors(slot_);
    in.reflectors = reflectors.buffer().reflectors(slot_);
    in.looseReflectors = reflectors.surfaces().loose(slot_);
    in.looseCount = reflectors.surfaces().looseCount();
    in.looseGlassReflectors = reflectors.surfaces().looseGlass(slot_);
    in.looseGlassCount = reflectors.surfaces().looseGlassCount();
    return in;
}

const std::vector<passes::PlanarView>& FrameConstantsBuffer::mirroredViews(const ReflectorSet& reflectors) {
    if (mirrored_) return *mirrored_;
    mirrored_.emplace();
    const std::vector<scene::Reflector>& list = reflectors.list();
    const scene::ReflectorGroups& groups = reflectors.buffer().groups();
    std::vector<int> representative(groups.planeGroupCount, -1);
    for (size_t i = 0; i < list.size(); ++i)
        if (scene::reflectorMaybeVisible(list[i], main_.viewProj, eye_) && representative[groups.planeGroup[i]] < 0)
            representative[groups.planeGroup[i]] = static_cast<int>(i);
    for (uint32_t group = 0; group < groups.planeGroupCount; ++group) {
        if (representative[group] < 0) continue;
        const scene::MirrorView mv = scene::mirrorView(main_.view, main_.proj, eye_, list[representative[group]]);
        gpu::FrameConstants f = main_;
        f.view = mv.view;
        f.proj = mv.proj;
        f.viewProj = mv.proj * mv.view;
        f.invViewProj = glm::inverse(f.viewProj);
        f.cameraPos = glm::vec4(mv.eye, main_.cameraPos.w);
        f.debugView = gpu::kDebugNone;
        f.mirrored = 1;
        const uint32_t view = 1 + static_cast<uint32_t>(mirrored_->size());
        write(view, f);
        mirrored_->push_back({group, inputs(reflectors, view)});
    }
    flush();
    return *mirrored_;
}

void FrameConstantsBuffer::write(uint32_t view, const gpu::FrameConstants& f) {
    const VkDeviceSize offset = (VkDeviceSize(slot_) * capacity_ + view) * stride_;
    std::memcpy(static_cast<char*>(buffer_.mapped) + offset, &f, sizeof(f));
}

void FrameConstantsBuffer::flush() {
    vmaFlushAllocation(ctx_.allocator(), buffer_.allocation, VkDeviceSize(slot_) * capacity_ * stride_, VkDeviceSize(capacity_) * stride_);
}

}  // namespace ppr::app
