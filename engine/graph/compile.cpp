// compile(): culling and usage derivation (barrier planning lives in barrier_plan.cpp).
// Passes keep their declaration order: a handle can only be read after the write that produced it,
// so declaration order is already a valid topological order and no sort is needed.
#include "graph/graph.hpp"
#include "graph/history.hpp"

#include <set>
#include <stdexcept>

namespace ppr::graph {

void RenderGraph::compile() {
    compiled_.clear();
    finalBarriers_.clear();
    endStates_.clear();
    for (const Resource& r : resources_) {
        const std::optional<Access>& fin = r.importedImage ? r.importedImage->finalAccess
                                           : r.importedBuffer ? r.importedBuffer->finalAccess
                                                              : std::optional<Access>{};
        if (fin && !r.isImage && *fin == Access::Present)
            throw std::runtime_error("graph: buffer '" + r.name + "' cannot have finalAccess present");
    }
    for (uint32_t i = 0; i < passes_.size(); ++i) compiled_.push_back({passes_[i].name, i, passes_[i].kind, false, {}});
    cull();
    deriveUsage();
    planBarriers();
    compiled = true;
}

// Reference counting as in Filament, done as one reverse walk: a reader is always declared after the
// producer of the version it reads, so when the walk reaches a pass all of its readers have already
// been decided and the walk reaches the fixed point in a single sweep.
void RenderGraph::cull() {
    auto key = [](uint32_t resource, uint32_t version) { return (uint64_t(resource) << 32) | version; };
    std::set<uint64_t> needed;  // (resource, version) read by a kept pass
    for (uint32_t i = static_cast<uint32_t>(passes_.size()); i-- > 0;) {
        const Pass& pass = passes_[i];
        bool keep = pass.sideEffect;
        for (const ResourceUse& u : pass.uses) {
            if (u.versionWritten == 0) continue;
            // A write to an import is observed outside this frame (swapchain, read-back, and a history
            // `current`, read as `previous` next frame), so it counts as a side effect.
            if (isImported(u.resource) || needed.count(key(u.resource, u.versionWritten))) keep = true;
        }
        compiled_[i].culled = !keep;
        if (!keep) continue;
        for (const ResourceUse& u : pass.uses)
            if (u.versionRead > 0) needed.insert(key(u.resource, u.versionRead));
    }
}

// Usage flags come only from what kept passes declared (and where imports end up), never from passes.
void RenderGraph::deriveUsage() {
    for (Resource& r : resources_) {
        r.imageUsage = 0;
        r.bufferUsage = 0;
        if (r.importedImage && r.importedImage->finalAccess) r.imageUsage |= imageUsageFor(*r.importedImage->finalAccess);
        if (r.importedBuffer && r.importedBuffer->finalAccess)
            r.bufferUsage |= bufferUsageFor(*r.importedBuffer->finalAccess);
    }
    for (const CompiledPass& cp : compiled_) {
        if (cp.culled) continue;
        for (const ResourceUse& u : passes_[cp.index].uses) {
            Resource& r = resources_[u.resource];
            if (u.isImage)
                r.imageUsage |= imageUsageFor(u.access);
            else
                r.bufferUsage |= bufferUsageFor(u.access);
        }
    }
}

void RenderGraph::commitImportStates() {
    if (!compiled) throw std::runtime_error("graph: commitImportStates() before compile()");
    for (uint32_t id = 0; id < resources_.size(); ++id) {
        const Resource& r = resources_[id];
        if (r.importedImage) r.importedImage->state = endStates_[id];
        // Buffers have no layout; keeping UNDEFINED there keeps state comparisons simple.
        if (r.importedBuffer) r.importedBuffer->state = {VK_IMAGE_LAYOUT_UNDEFINED, endStates_[id].stage, endStates_[id].access};
    }
    // Only a kept pass's write makes `current` worth reading next frame.
    for (const HistoryUse& h : histories_)
        for (const CompiledPass& cp : compiled_) {
            if (cp.culled) continue;
            for (const ResourceUse& u : passes_[cp.index].uses)
                if (u.resource == h.current && u.versionWritten > 0) h.store->markWritten(h.name);
        }
}

std::vector<std::string> RenderGraph::culledPasses() const {
    std::vector<std::string> names;
    for (const CompiledPass& cp : compiled_)
        if (cp.culled) names.push_back(cp.name);
    return names;
}

std::string RenderGraph::cullLog() const {
    std::string log;
    for (const CompiledPass& cp : compiled_) {
        if (!cp.culled) continue;
        std::string outputs;
        for (const ResourceUse& u : passes_[cp.index].uses) {
            if (u.versionWritten == 0) continue;
            outputs += (outputs.empty() ? "" : ", ") + resources_[u.resource].name;
        }
        if (!log.empty()) log += '\n';
        log += "graph: culled pass '" + cp.name + "' (" +
               (outputs.empty() ? std::string("writes nothing and has no sideEffect()") : "nothing reads: " + outputs) +
               ")";
    }
    return log;
}

}  // namespace ppr::graph
