#pragma once
// The scene's ray-query acceleration structures (VK_KHR_acceleration_structure): one bottom-level
// structure per mesh that an opaque draw uses, one top-level structure over the opaque draws
// (instance transform = the draw's world matrix, instanceCustomIndex = the draw index, so a hit finds
// its DrawData and, through it, its material and triangles). Transparent (glass) draws are left out,
// as the G-buffer and the planar reference's mirrored G-buffers leave them out.
//
// Built once, in one load-time submit, when constructed; nothing is rebuilt per frame. The scene is
// static: a moving draw would need a TLAS rebuild (or an update of an ALLOW_UPDATE build) with its new
// transform, a deforming mesh a BLAS rebuild/refit, a scene change a new object.
#include "gpu/gpu_scene.hpp"

#include <cstdint>
#include <vector>

namespace ppr::gpu {

class SceneAccelerationStructures {
public:
    // Requires ctx.rayQuery().available (throws std::logic_error otherwise).
    SceneAccelerationStructures(const vk::Context& ctx, const GpuScene& scene);
    ~SceneAccelerationStructures();
    SceneAccelerationStructures(const SceneAccelerationStructures&) = delete;
    SceneAccelerationStructures& operator=(const SceneAccelerationStructures&) = delete;

    VkAccelerationStructureKHR tlas() const { return tlas_.handle; }

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

    const vk::Context& ctx_;
    std::vector<Structure> blas_;
    Structure tlas_;
    Stats stats_;
};

}  // namespace ppr::gpu
