#include "gpu/acceleration_structures.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

namespace ppr::gpu {
namespace {

VkDeviceAddress bufferAddress(const vk::Context& ctx, VkBuffer buffer) {
    VkBufferDeviceAddressInfo info{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
    info.buffer = buffer;
    return vkGetBufferDeviceAddress(ctx.device(), &info);
}

VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) { return (v + a - 1) / a * a; }

// Build → next use: the structures' writes made visible to later builds (the TLAS reads the BLASes)
// and to shaders (ray queries).
void buildBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    mb.srcStageMask = VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR;
    mb.srcAccessMask = VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    mb.dstStageMask = dstStage;
    mb.dstAccessMask = dstAccess;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = 1;
    dep.pMemoryBarriers = &mb;
    vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

SceneAccelerationStructures::Structure SceneAccelerationStructures::create(VkAccelerationStructureTypeKHR type, VkDeviceSize bytes,
                                                                           const std::string& name) {
    const vk::RayQuerySupport& rq = ctx_.rayQuery();
    Structure s;
    s.storage = vk::createBuffer(ctx_, bytes, VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                 vk::MemoryUse::GpuOnly, name);
    VkAccelerationStructureCreateInfoKHR ci{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    ci.buffer = s.storage.buffer;
    ci.size = bytes;
    ci.type = type;
    VK_CHECK(rq.createAccelerationStructure(ctx_.device(), &ci, nullptr, &s.handle));
    ctx_.name(s.handle, VK_OBJECT_TYPE_ACCELERATION_STRUCTURE_KHR, name);
    VkAccelerationStructureDeviceAddressInfoKHR ai{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
    ai.accelerationStructure = s.handle;
    s.address = rq.getDeviceAddress(ctx_.device(), &ai);
    stats_.bytes += bytes;
    return s;
}

void SceneAccelerationStructures::destroy(Structure& s) {
    if (s.handle) ctx_.rayQuery().destroyAccelerationStructure(ctx_.device(), s.handle, nullptr);
    vk::destroyBuffer(ctx_, s.storage);
    s = {};
}

SceneAccelerationStructures::SceneAccelerationStructures(const vk::Context& ctx, const GpuScene& gpuScene, uint32_t framesInFlight)
    : ctx_(ctx) {
    const vk::RayQuerySupport& rq = ctx.rayQuery();
    if (!rq.available) throw std::logic_error("acceleration structures: " + ctx.rayQueryUnavailableReason());
    const auto start = std::chrono::steady_clock::now();
    const scene::Scene& scene = gpuScene.cpu();
    const VkDeviceAddress vertices = bufferAddress(ctx, gpuScene.vertexBuffer());
    const VkDeviceAddress indices = bufferAddress(ctx, gpuScene.indexBuffer());

    // One BLAS per mesh an opaque draw uses (a mesh drawn twice is built once).
    std::map<uint32_t, uint32_t> blasOfMesh;  // mesh → index into blas_
    struct BlasBuild {
        VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
        VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
        VkAccelerationStructureBuildRangeInfoKHR range{};
        VkDeviceSize scratchOffset = 0;
    };
    std::vector<BlasBuild> builds;
    builds.reserve(scene.meshes.size());
    VkDeviceSize scratchBytes = 0;
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const uint32_t meshIndex = scene.draws[d].mesh;
        const scene::Mesh& mesh = scene.meshes[meshIndex];
        if (gpuScene.transparent(d) || mesh.indexCount < 3 || blasOfMesh.count(meshIndex)) continue;
        uint32_t maxVertex = 0;
        for (uint32_t i = 0; i < mesh.indexCount; ++i) maxVertex = std::max(maxVertex, scene.indices[mesh.firstIndex + i]);
        BlasBuild b;
        VkAccelerationStructureGeometryTrianglesDataKHR& tri = b.geometry.geometry.triangles;
        tri = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR};
        tri.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;  // scene::Vertex::position, first member
        tri.vertexData.deviceAddress = vertices + VkDeviceAddress(int64_t(mesh.vertexOffset) * int64_t(sizeof(scene::Vertex)));
        tri.vertexStride = sizeof(scene::Vertex);
        tri.maxVertex = maxVertex;
        tri.indexType = VK_INDEX_TYPE_UINT32;
        tri.indexData.deviceAddress = indices + VkDeviceAddress(mesh.firstIndex) * sizeof(uint32_t);
        b.geometry.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
        // Alpha-masked materials (glTF MASK) are not opaque: the ray query tests their alpha per candidate.
        const bool masked = mesh.material >= 0 && size_t(mesh.material) < scene.materials.size() && scene.materials[size_t(mesh.material)].masked;
        b.geometry.flags = masked ? VkGeometryFlagsKHR(0) : VkGeometryFlagsKHR(VK_GEOMETRY_OPAQUE_BIT_KHR);
        b.info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
        b.info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
        b.info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
        b.info.geometryCount = 1;
        b.range.primitiveCount = mesh.indexCount / 3;
        VkAccelerationStructureBuildSizesInfoKHR sizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
        b.info.pGeometries = &b.geometry;
        rq.getBuildSizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &b.info, &b.range.primitiveCount, &sizes);
        blasOfMesh[meshIndex] = static_cast<uint32_t>(blas_.size());
        blas_.push_back(create(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, sizes.accelerationStructureSize, "blas " + mesh.name));
        b.info.dstAccelerationStructure = blas_.back().handle;
        b.scratchOffset = scratchBytes;
        scratchBytes = alignUp(scratchBytes + sizes.buildScratchSize, rq.scratchAlignment);
        stats_.triangles += b.range.primitiveCount;
        builds.push_back(b);
    }

    // The TLAS: one instance per opaque draw.
    std::vector<VkAccelerationStructureInstanceKHR> instances;
    std::vector<uint32_t> instanceDraws;
    for (uint32_t d = 0; d < scene.draws.size(); ++d) {
        const auto blas = blasOfMesh.find(scene.draws[d].mesh);
        if (gpuScene.transparent(d) || blas == blasOfMesh.end()) continue;
        if (d >= (1u << 24)) throw std::runtime_error("acceleration structures: more than 2^24 draws (instanceCustomIndex holds the draw index)");
        VkAccelerationStructureInstanceKHR inst{};
        const glm::mat4& w = scene.draws[d].world;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 4; ++col) inst.transform.matrix[row][col] = w[col][row];
        inst.instanceCustomIndex = d;
        inst.mask = 0xFF;
        inst.instanceShaderBindingTableRecordOffset = 0;
        inst.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR;  // two-sided, as the G-buffer draws it
        inst.accelerationStructureReference = blas_[blas->second].address;
        instances.push_back(inst);
        instanceDraws.push_back(d);
    }
    vk::Buffer instanceBuffer = uploadBuffer(ctx, instances.data(), instances.size() * sizeof(VkAccelerationStructureInstanceKHR),
                                             VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                             "tlas instances");
    VkAccelerationStructureGeometryKHR tlasGeometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    tlasGeometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    tlasGeometry.geometry.instances = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR};
    tlasGeometry.geometry.instances.data.deviceAddress = bufferAddress(ctx, instanceBuffer.buffer);
    VkAccelerationStructureBuildGeometryInfoKHR tlasInfo{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    tlasInfo.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    tlasInfo.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    tlasInfo.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    tlasInfo.geometryCount = 1;
    tlasInfo.pGeometries = &tlasGeometry;
    VkAccelerationStructureBuildRangeInfoKHR tlasRange{};
    tlasRange.primitiveCount = static_cast<uint32_t>(instances.size());
    VkAccelerationStructureBuildSizesInfoKHR tlasSizes{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    rq.getBuildSizes(ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &tlasInfo, &tlasRange.primitiveCount, &tlasSizes);
    tlas_ = create(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, tlasSizes.accelerationStructureSize, "tlas");
    tlasInfo.dstAccelerationStructure = tlas_.handle;
    // The TLAS build runs after the BLAS builds (a barrier between), so it may reuse their scratch.
    scratchBytes = std::max(scratchBytes, alignUp(tlasSizes.buildScratchSize, rq.scratchAlignment));

    vk::Buffer scratch = vk::createBuffer(ctx, std::max<VkDeviceSize>(scratchBytes + rq.scratchAlignment, 16),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, vk::MemoryUse::GpuOnly,
                                          "acceleration structure scratch");
    const VkDeviceAddress scratchBase = alignUp(bufferAddress(ctx, scratch.buffer), rq.scratchAlignment);
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> ranges;
    for (BlasBuild& b : builds) {
        b.info.pGeometries = &b.geometry;  // `builds` no longer moves
        b.info.scratchData.deviceAddress = scratchBase + b.scratchOffset;
        infos.push_back(b.info);
        ranges.push_back(&b.range);
    }
    tlasInfo.scratchData.deviceAddress = scratchBase;
    const VkAccelerationStructureBuildRangeInfoKHR* tlasRanges = &tlasRange;
    ctx.immediateSubmit([&](VkCommandBuffer cmd) {
        if (!infos.empty()) rq.cmdBuild(cmd, static_cast<uint32_t>(infos.size()), infos.data(), ranges.data());
        // The TLAS reads the BLASes and reuses their scratch memory.
        buildBarrier(cmd, VK_PIPELINE_STAGE_2_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                     VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR);
        rq.cmdBuild(cmd, 1, &tlasInfo, &tlasRanges);
        // Load time: visible to every later ray query (frames are separate submits).
        buildBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_ACCELERATION_STRUCTURE_READ_BIT_KHR);
    });
    vk::destroyBuffer(ctx, scratch);
    vk::destroyBuffer(ctx, instanceBuffer);
    if (gpuScene.animated()) {
        instances_ = std::move(instances);
        createRebuildResources(gpuScene, instanceDraws, tlasSizes.buildScratchSize, framesInFlight);
    }
    stats_.bottomLevel = static_cast<uint32_t>(blas_.size());
    stats_.instances = static_cast<uint32_t>(instanceDraws.size());
    stats_.buildMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void SceneAccelerationStructures::createRebuildResources(const GpuScene& gpuScene, const std::vector<uint32_t>& instanceDraws,
                                                         VkDeviceSize scratchBytes, uint32_t framesInFlight) {
    const vk::RayQuerySupport& rq = ctx_.rayQuery();
    const scene::SceneAnimation& animation = gpuScene.cpu().animation;
    for (uint32_t draw : animation.draws) {
        const auto it = std::lower_bound(instanceDraws.begin(), instanceDraws.end(), draw);
        movingInstance_.push_back(it != instanceDraws.end() && *it == draw ? int(it - instanceDraws.begin()) : -1);
    }
    const VkDeviceSize bytes = std::max<VkDeviceSize>(instances_.size() * sizeof(VkAccelerationStructureInstanceKHR), 16);
    for (uint32_t s = 0; s < framesInFlight; ++s) {
        vk::Buffer b = vk::createBuffer(ctx_, bytes,
                                        VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                        vk::MemoryUse::Upload, "tlas instances (moving)");
        std::memcpy(b.mapped, instances_.data(), instances_.size() * sizeof(VkAccelerationStructureInstanceKHR));
        vmaFlushAllocation(ctx_.allocator(), b.allocation, 0, VK_WHOLE_SIZE);
        slots_.push_back(b);
    }
    rebuildScratch_ = vk::createBuffer(ctx_, std::max<VkDeviceSize>(scratchBytes + rq.scratchAlignment, 16),
                                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, vk::MemoryUse::GpuOnly,
                                       "tlas rebuild scratch");
}

void SceneAccelerationStructures::prepareRebuild(uint32_t slot, const GpuScene& gpuScene) {
    const SceneMotion* motion = gpuScene.motion();
    if (!motion || slot >= slots_.size()) return;
    auto* out = static_cast<VkAccelerationStructureInstanceKHR*>(slots_[slot].mapped);
    const std::vector<glm::mat4>& worlds = motion->worlds();
    for (size_t i = 0; i < movingInstance_.size() && i < worlds.size(); ++i) {
        if (movingInstance_[i] < 0) continue;
        VkTransformMatrixKHR& t = out[movingInstance_[i]].transform;
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 4; ++col) t.matrix[row][col] = worlds[i][col][row];
    }
    vmaFlushAllocation(ctx_.allocator(), slots_[slot].allocation, 0, VK_WHOLE_SIZE);
}

void SceneAccelerationStructures::recordRebuild(VkCommandBuffer cmd, uint32_t slot) const {
    const vk::RayQuerySupport& rq = ctx_.rayQuery();
    VkAccelerationStructureGeometryKHR geometry{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    geometry.geometry.instances = {VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR};
    geometry.geometry.instances.data.deviceAddress = bufferAddress(ctx_, slots_[slot].buffer);
    VkAccelerationStructureBuildGeometryInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;  // a full build each frame: no update bookkeeping, no quality drift
    info.geometryCount = 1;
    info.pGeometries = &geometry;
    info.dstAccelerationStructure = tlas_.handle;
    info.scratchData.deviceAddress = alignUp(bufferAddress(ctx_, rebuildScratch_.buffer), rq.scratchAlignment);
    VkAccelerationStructureBuildRangeInfoKHR range{};
    range.primitiveCount = static_cast<uint32_t>(instances_.size());
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
    rq.cmdBuild(cmd, 1, &info, &ranges);
}

SceneAccelerationStructures::~SceneAccelerationStructures() {
    vkDeviceWaitIdle(ctx_.device());
    for (vk::Buffer& b : slots_) vk::destroyBuffer(ctx_, b);
    vk::destroyBuffer(ctx_, rebuildScratch_);
    destroy(tlas_);
    for (Structure& s : blas_) destroy(s);
}

}  // namespace ppr::gpu
