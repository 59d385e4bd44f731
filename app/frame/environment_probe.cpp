#include "frame/environment_probe.hpp"

#include "graph/executor.hpp"
#include "scene/camera.hpp"

#include <chrono>
#include <cstring>

namespace ppr::app {
namespace {

// Face constants rounded up to 256 bytes apart (≥ minUniformBufferOffsetAlignment, as FrameConstantsBuffer).
constexpr VkDeviceSize kFaceStride = (sizeof(gpu::FrameConstants) + 255) / 256 * 256;

}  // namespace

EnvironmentProbe::EnvironmentProbe(const vk::Context& ctx, const gpu::GpuScene& scene, const passes::ShadowPass& shadow,
                                   const passes::GBufferPass& gbuffer, const passes::LightingPass& lighting)
    : ctx_(ctx), scene_(scene), pass_(ctx, shadow, gbuffer, lighting) {
    cube_ = vk::createCubeImage(ctx, gpu::kEnvProbeFaceSize, passes::EnvProbePass::kFormat,
                                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT, "env.probe");
    const graph::ImageDesc desc{gpu::kEnvProbeFaceSize, gpu::kEnvProbeFaceSize, passes::EnvProbePass::kFormat, 1};
    sampled_ = {cube_.image, cube_.cubeView, desc, {}, std::nullopt};
    layers_ = {cube_.image, cube_.layersView, desc, {}, std::nullopt};
    data_ = vk::createBuffer(ctx, sizeof(gpu::EnvProbeData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload, "env.probe data");
    std::memset(data_.mapped, 0, sizeof(gpu::EnvProbeData));  // bound before the first render, read only after it
    vmaFlushAllocation(ctx.allocator(), data_.allocation, 0, VK_WHOLE_SIZE);
    faces_ = vk::createBuffer(ctx, kFaceStride * passes::EnvProbePass::kFaces, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload,
                              "env.probe faces");
}

EnvironmentProbe::~EnvironmentProbe() {
    vk::destroyBuffer(ctx_, faces_);
    vk::destroyBuffer(ctx_, data_);
    vk::destroyCubeImage(ctx_, cube_);
}

void EnvironmentProbe::prepare(const passes::FrameInputs& in, const gpu::FrameConstants& main, const std::vector<scene::Reflector>& reflectors,
                               uint32_t shadowRes) {
    if (renders_ > 0) return;
    const auto start = std::chrono::steady_clock::now();
    Stats stats;
    stats.placement = scene::placeProbe(scene_.cpu(), reflectors);
    const glm::vec3 centre = stats.placement.centre;
    const gpu::EnvProbeData data{glm::vec4(centre, 0.0f), glm::vec4(stats.placement.boxMin, 0.0f), glm::vec4(stats.placement.boxMax, 0.0f)};
    std::memcpy(data_.mapped, &data, sizeof(data));
    vmaFlushAllocation(ctx_.allocator(), data_.allocation, 0, VK_WHOLE_SIZE);

    // Six square 90° views from the centre, lit as this frame is (light, sky, shadow projection).
    std::array<passes::FrameInputs, passes::EnvProbePass::kFaces> faces;
    const float size = static_cast<float>(gpu::kEnvProbeFaceSize);
    for (uint32_t face = 0; face < faces.size(); ++face) {
        gpu::FrameConstants f = main;
        f.view = passes::EnvProbePass::faceView(face, centre);
        f.proj = scene::projectionMatrix(90.0f, 1.0f, scene::kNearPlane);
        f.viewProj = f.proj * f.view;
        f.invViewProj = glm::inverse(f.viewProj);
        f.cameraPos = glm::vec4(centre, scene::kNearPlane);
        f.screenSize = glm::vec2(size);
        f.invScreenSize = glm::vec2(1.0f / size);
        f.debugView = gpu::kDebugNone;
        f.mirrored = 0;
        std::memcpy(static_cast<char*>(faces_.mapped) + face * kFaceStride, &f, sizeof(f));
        faces[face] = in;
        faces[face].frameConstants = faces_.buffer;
        faces[face].frameConstantsOffset = face * kFaceStride;
        faces[face].frameConstantsSize = sizeof(gpu::FrameConstants);
        faces[face].extent = {gpu::kEnvProbeFaceSize, gpu::kEnvProbeFaceSize};
    }
    vmaFlushAllocation(ctx_.allocator(), faces_.allocation, 0, VK_WHOLE_SIZE);

    // A graph and an executor of its own: its transients are freed with it, and no frame's pass list
    // or timings change. The cube carries its state from the frames' imports and back.
    {
        graph::GraphExecutor executor(ctx_, 1);
        graph::RenderGraph g;
        layers_.state = sampled_.state;
        pass_.add(g, faces, shadowRes, g.importImage("env.probe", &layers_));
        g.compile();
        ctx_.immediateSubmit([&](VkCommandBuffer cmd) { executor.execute(g, cmd, 0); });
        sampled_.state = layers_.state;
        for (const graph::PassTiming& t : executor.readTimings(0)) stats.gpuMs += t.gpuMs;
    }
    stats.bytes = cube_.bytes;
    stats.wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats_ = stats;
    ++renders_;
}

passes::Environment EnvironmentProbe::bind(graph::RenderGraph& g, bool fallback, bool probe) {
    passes::Environment env;
    env.fallback = fallback;
    env.probe = fallback && probe && renders_ > 0;
    env.probeData = data_.buffer;
    env.probeCube = g.importImage("env.probe", &sampled_);
    return env;
}

}  // namespace ppr::app
