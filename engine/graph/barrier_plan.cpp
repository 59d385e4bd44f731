// Barrier planning as plain data: walk the kept passes in order and, per resource, compare what the
// pass needs (from the access table) with the state the resource was left in. Each rule below is the
// smallest barrier that is still correct for the hazard it covers (RAW, WAR, WAW, layout change).
#include "graph/graph.hpp"

#include <utility>

namespace ppr::graph {

namespace {

// Only write bits make memory available; read bits in a source access mask mean nothing.
constexpr VkAccessFlags2 kWriteBits =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT |
    VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;

// What the planner knows about one resource at a point of the frame.
struct Track {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool hasWrite = false;  // a write (or layout transition) earlier that later accesses must wait for
    VkPipelineStageFlags2 writeStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 writeAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 readStages = VK_PIPELINE_STAGE_2_NONE;  // reads since that write (for WAR)
    std::vector<std::pair<VkPipelineStageFlags2, VkAccessFlags2>> visible;  // made visible since that write
    bool firstUse = false;  // transient not touched yet this frame

    // True when every (stage, access bit) pair asked for has already been made visible.
    bool covered(VkPipelineStageFlags2 stage, VkAccessFlags2 access) const {
        for (VkAccessFlags2 bit = 1; bit != 0 && bit <= access; bit <<= 1) {
            if (!(access & bit)) continue;
            VkPipelineStageFlags2 stages = 0;
            for (const auto& [s, a] : visible)
                if (a & bit) stages |= s;
            if ((stages & stage) != stage) return false;
        }
        return true;
    }
    VkPipelineStageFlags2 waitStages() const { return (hasWrite ? writeStage : 0) | readStages; }
    void wrote(VkPipelineStageFlags2 stage, VkAccessFlags2 access) {
        hasWrite = true;
        writeStage = stage;
        writeAccess = access & kWriteBits;
        readStages = 0;
        visible.clear();
    }
};

}  // namespace

void RenderGraph::planBarriers() {
    std::vector<Track> tracks(resources_.size());
    for (uint32_t id = 0; id < resources_.size(); ++id) {
        const Resource& r = resources_[id];
        Track& t = tracks[id];
        const ResourceState* ext = r.importedImage ? &r.importedImage->state
                                   : r.importedBuffer ? &r.importedBuffer->state
                                                      : nullptr;
        if (!ext) {
            t.firstUse = true;  // pooled memory: the previous frame may still be using it
            continue;
        }
        t.layout = r.isImage ? ext->layout : VK_IMAGE_LAYOUT_UNDEFINED;
        if (ext->stage != VK_PIPELINE_STAGE_2_NONE) t.wrote(ext->stage, ext->access);
    }

    for (CompiledPass& cp : compiled_) {
        if (cp.culled) continue;
        for (const ResourceUse& u : passes_[cp.index].uses) {
            const Resource& r = resources_[u.resource];
            Track& t = tracks[u.resource];
            const AccessInfo info = accessInfo(u.access, cp.kind, r.isImage && isDepthFormat(r.imageDesc.format));
            const VkImageLayout layout = r.isImage ? info.layout : VK_IMAGE_LAYOUT_UNDEFINED;

            PlannedBarrier b;
            b.resource = u.resource;
            b.isImage = r.isImage;
            b.dstStage = info.stage;
            b.dstAccess = info.access;
            bool emit = false;
            bool transition = false;
            if (t.firstUse) {
                // Contents are discarded (UNDEFINED), but whatever last used the pooled memory (the
                // previous frame, earlier on this queue) must be done; its writes made available too,
                // since write-after-write needs a memory dependency, not only an execution one.
                b.srcStage = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
                b.srcAccess = VK_ACCESS_2_MEMORY_WRITE_BIT;
                b.newLayout = layout;
                emit = transition = true;
            } else if (layout != t.layout) {
                // A layout transition is a write: it waits for the last write and every read since.
                b.srcStage = t.waitStages();
                b.srcAccess = t.hasWrite ? t.writeAccess : VK_ACCESS_2_NONE;
                b.oldLayout = t.layout;
                b.newLayout = layout;
                emit = transition = true;
            } else if (info.writes) {
                // WAW needs the last write made available; WAR only needs the readers to have finished.
                b.srcStage = t.waitStages();
                b.srcAccess = t.hasWrite ? t.writeAccess : VK_ACCESS_2_NONE;
                b.oldLayout = b.newLayout = layout;
                emit = b.srcStage != VK_PIPELINE_STAGE_2_NONE;
            } else if (t.hasWrite && !t.covered(info.stage, info.access)) {
                // RAW: make the last write visible to this stage/access once; later readers reuse it.
                b.srcStage = t.writeStage;
                b.srcAccess = t.writeAccess;
                b.oldLayout = b.newLayout = layout;
                emit = true;
            }
            if (emit) cp.barriers.push_back(b);

            t.firstUse = false;
            t.layout = layout;
            if (info.writes) {
                t.wrote(info.stage, info.access);
            } else if (transition) {
                // The transition is the new "write"; it was made visible to exactly this access.
                t.wrote(info.stage, VK_ACCESS_2_NONE);
                t.readStages = info.stage;
                t.visible.push_back({info.stage, info.access});
            } else {
                if (emit) t.visible.push_back({info.stage, info.access});
                t.readStages |= info.stage;
            }
        }
    }

    // End of frame: where each resource is left, and the transition of imports to their final access.
    endStates_.assign(resources_.size(), {});
    for (uint32_t id = 0; id < resources_.size(); ++id) {
        const Resource& r = resources_[id];
        const Track& t = tracks[id];
        endStates_[id] = {t.layout, t.waitStages(), t.hasWrite ? t.writeAccess : VK_ACCESS_2_NONE};
        const std::optional<Access>& fin = r.importedImage ? r.importedImage->finalAccess
                                           : r.importedBuffer ? r.importedBuffer->finalAccess
                                                              : std::optional<Access>{};
        if (!fin) continue;
        const AccessInfo info = accessInfo(*fin, QueueKind::Graphics, r.isImage && isDepthFormat(r.imageDesc.format));
        PlannedBarrier b;
        b.resource = id;
        b.isImage = r.isImage;
        // Present: nothing in the queue waits (the semaphore does); BOTTOM_OF_PIPE says so explicitly.
        b.dstStage = info.stage != VK_PIPELINE_STAGE_2_NONE ? info.stage : VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT;
        b.dstAccess = info.access;
        b.oldLayout = t.layout;
        b.newLayout = r.isImage ? info.layout : VK_IMAGE_LAYOUT_UNDEFINED;
        bool emit = false;
        if (b.oldLayout != b.newLayout || info.writes) {
            b.srcStage = t.waitStages();
            b.srcAccess = t.hasWrite ? t.writeAccess : VK_ACCESS_2_NONE;
            emit = b.oldLayout != b.newLayout || b.srcStage != VK_PIPELINE_STAGE_2_NONE;
        } else if (t.hasWrite && !t.covered(info.stage, info.access)) {
            b.srcStage = t.writeStage;
            b.srcAccess = t.writeAccess;
            emit = true;
        }
        if (!emit) continue;
        finalBarriers_.push_back(b);
        endStates_[id] = {b.newLayout, b.dstStage, VK_ACCESS_2_NONE};
    }
}

}  // namespace ppr::graph
