#pragma once
// The scene's ray-query acceleration structures (VK_KHR_acceleration_structure): one bottom-level
// structure per mesh that an opaque draw uses, one top-level structure over the opaque draws
// (instance transform = the draw's world matrix, instanceCustomIndex = the draw index, so a hit finds
// its DrawData and, through it, its material and triangles). Transparent (glass) draws are left out,
// as the G-buffer and the planar reference's mirrored G-buffers leave them out.
//
// Built once, in one load-time submit, when constructed. A still scene rebuilds nothing per frame. An
// animated scene (GpuScene::animated()) rebuilds the TLAS each frame it is used, from per-frame-in-
// flight host-visible instance buffers whose moving entries take the frame's pose; the BLASes never
// change (rigid motion only). A deforming mesh would need a BLAS refit, a scene change a new object.
#include "gpu/gpu_scene.hpp"

#include <cstdint>
#include <vector>

namespace ppr::gpu {

class SceneAccelerationStructures {
public:
    // Requires ctx.rayQuery().available (throws std::logic_error otherwise).
    SceneAccelerationStructures(const vk::Context& ctx, const GpuScene& scene, uint32_t framesInFlight = 1);
    ~SceneAccelerationStructures();
    SceneAccelerationStructures(const SceneAccelerationStructures&) = delete;
    SceneAccelerationStructures& operator=(const SceneAccelerationStructures&) = delete;

    VkAccelerationStructureKHR tlas() const { return tlas_.handle; }

    // Animated scenes: the per-frame TLAS rebuild. prepareRebuild() writes frame `slot`'s moving
    // instances from the scene's current pose (host writes, after the slot's fence); recordRebuild()
    // records the build, in a pass that declares tlasStorage() and scratchBuffer() as built and
    // whose readers declare tlasStorage() as read.
    bool rebuildsPerFrame() const { return !slots_.empty(); }
    void prepareRebuild(uint32_t slot, const GpuScene& scene);
    void recordRebuild(VkCommandBuffer cmd, uint32_t slot) const;
    VkBuffer tlasStorage() const { return tlas_.storage.buffer; }
    VkDeviceSize tlasStorageBytes() const { return tlas_.storage.size; }
    VkBuffer scratchBuffer() const { return rebuildScratch_.buffer; }
    VkDeviceSize scratchBytes() const { return rebuildScratch_.size; }

    struct Stats {
        uint32_t bottomLevel = 0;  // BLASes (meshes of opaque draws)
        uint32_t instances = 0;    // TLAS instances (opaque draws)
        uint64_t triangles = 0;    // over the BLASes
        uint64_t bytes = 0;        // acceleration-structure storage
        double buildMs = 0.0;      // CPU wall time of the load-time build (submit + wait)
    };
    const Stats& stats() const { return stats_; }

private:
    struct Structure {
        VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
        vk::Buffer storage;
        VkDeviceAddress address = 0;
    };
    Structure create(VkAccelerationStructureTypeKHR type, VkDeviceSize bytes, const std::string& name);
    void destroy(Structure& s);

    void createRebuildResources(const GpuScene& scene, const std::vector<uint32_t>& instanceDraws, VkDeviceSize scratchBytes,
                                uint32_t framesInFlight);

    const vk::Context& ctx_;
    std::vector<Structure> blas_;
    Structure tlas_;
    Stats stats_;
    // Per-frame rebuild (animated scenes only).
    std::vector<VkAccelerationStructureInstanceKHR> instances_;  // at rest
    std::vector<int> movingInstance_;                            // per SceneAnimation::draws entry: its instance, or -1
    std::vector<vk::Buffer> slots_;                              // instance buffers, one per frame in flight
    vk::Buffer rebuildScratch_;
};

}  // namespace ppr::gpu
