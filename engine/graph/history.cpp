// HistoryStore bookkeeping (ping-pong, validity, resets) and RenderGraph::history, which imports the
// pair into a frame's graph. No Vulkan call here: allocation goes through the injected allocator.
#include "graph/history.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace ppr::graph {

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error("graph: " + message); }

std::string label(const std::string& name) { return "history '" + name + "'"; }

// Why a changed descriptor invalidates the history, for the reset log.
std::string changeReason(const ImageDesc& from, const ImageDesc& to) {
    if (from.width != to.width || from.height != to.height) return "resize";
    if (from.format != to.format) return "format change";
    return "mip levels change";
}

}  // namespace

HistoryStore::HistoryStore(HistoryAllocator allocator) : allocator_(std::move(allocator)) {}

HistoryStore::~HistoryStore() {
    for (auto& [name, e] : entries_) {
        try {
            release(e);
        } catch (...) {
            // A destructor cannot report; a failing free at teardown means the device is lost anyway.
        }
    }
}

// ---- allocation ----------------------------------------------------------------------------------

void HistoryStore::allocate(const std::string& name, Entry& e) {
    if (e.isImage ? !(allocator_.createImage && allocator_.destroyImage)
                  : !(allocator_.createBuffer && allocator_.destroyBuffer))
        fail(label(name) + ": the store has no " + (e.isImage ? "image" : "buffer") + " allocator");
    for (int i = 0; i < 2; ++i) {
        const std::string slotName = name + (i == 0 ? "#0" : "#1");
        try {
            // Fresh memory: contents undefined, nothing to wait for.
            if (e.isImage) {
                ExternalImage img = allocator_.createImage(slotName, e.imageDesc);
                if (!img.image) fail(label(name) + ": the allocator returned a null image");
                e.images[i] = {img.image, img.view, e.imageDesc, {}, std::nullopt};
            } else {
                ExternalBuffer buf = allocator_.createBuffer(slotName, e.bufferDesc);
                if (!buf.buffer) fail(label(name) + ": the allocator returned a null buffer");
                e.buffers[i] = {buf.buffer, e.bufferDesc, {}, std::nullopt};
            }
        } catch (...) {
            if (i == 1) {  // do not leak the half-made pair
                if (e.isImage) allocator_.destroyImage(e.images[0]);
                else allocator_.destroyBuffer(e.buffers[0]);
            }
            throw;
        }
    }
}

void HistoryStore::release(Entry& e) {
    for (int i = 0; i < 2; ++i) {
        if (e.isImage && e.images[i].image) allocator_.destroyImage(e.images[i]);
        if (!e.isImage && e.buffers[i].buffer) allocator_.destroyBuffer(e.buffers[i]);
        e.images[i] = {};
        e.buffers[i] = {};
    }
}

// ---- per-frame requests --------------------------------------------------------------------------

HistoryStore::Entry& HistoryStore::begin(const std::string& name, bool isImage) {
    Entry& e = entries_.at(name);
    if (e.isImage != isImage)
        fail(label(name) + " is " + (e.isImage ? "an image" : "a buffer") + ", requested as " +
             (isImage ? "an image" : "a buffer"));
    // Two requests in one frame would hand out the same `current` twice, or mean endFrame() is missing
    // and the pair never swaps; both silently break temporal filters.
    if (e.requested) fail(label(name) + " requested twice in one frame (endFrame() not called since?)");
    e.lastRequestedFrame = frame_;
    return e;
}

HistoryStore::Pair<ExternalImage> HistoryStore::requestImage(const std::string& name, const ImageDesc& desc) {
    if (desc.width == 0 || desc.height == 0 || desc.format == VK_FORMAT_UNDEFINED || desc.mipLevels == 0)
        fail(label(name) + " has an empty extent, no mip level or an undefined format");
    if (!entries_.count(name)) {
        Entry e;
        e.imageDesc = desc;
        allocate(name, e);  // before inserting, so a failed allocation leaves no half entry
        entries_.emplace(name, std::move(e));
    }
    Entry& e = begin(name, true);
    if (e.imageDesc != desc) {
        // New pair first, old one freed after: a failed allocation leaves the entry as it was.
        const std::string reason = changeReason(e.imageDesc, desc);
        Entry fresh = e;
        fresh.imageDesc = desc;
        allocate(name, fresh);
        release(e);
        e.imageDesc = desc;
        std::copy(std::begin(fresh.images), std::end(fresh.images), std::begin(e.images));
        resetEntry(name, e, reason);
    }
    e.requested = true;
    return {&e.images[1 - e.current], &e.images[e.current], e.previousValid};
}

HistoryStore::Pair<ExternalBuffer> HistoryStore::requestBuffer(const std::string& name, const BufferDesc& desc) {
    if (desc.size == 0) fail(label(name) + " has size 0");
    if (!entries_.count(name)) {
        Entry e;
        e.isImage = false;
        e.bufferDesc = desc;
        allocate(name, e);
        entries_.emplace(name, std::move(e));
    }
    Entry& e = begin(name, false);
    if (e.bufferDesc != desc) {
        Entry fresh = e;
        fresh.bufferDesc = desc;
        allocate(name, fresh);
        release(e);
        e.bufferDesc = desc;
        std::copy(std::begin(fresh.buffers), std::end(fresh.buffers), std::begin(e.buffers));
        resetEntry(name, e, "resize");
    }
    e.requested = true;
    return {&e.buffers[1 - e.current], &e.buffers[e.current], e.previousValid};
}

void HistoryStore::markWritten(const std::string& name) {
    auto it = entries_.find(name);
    if (it != entries_.end() && it->second.requested) it->second.written = true;
}

void HistoryStore::endFrame() {
    for (auto& [name, e] : entries_) {
        if (e.requested) {
            e.current ^= 1u;
            const bool valid = e.written && !e.resetAfterRequest;
            // Say why history that was good is lost; a reset after the request is already logged.
            if (!valid && e.previousValid && !e.resetAfterRequest) resetEntry(name, e, "current not written");
            e.previousValid = valid;
        } else if (e.previousValid) {
            resetEntry(name, e, "unused for a frame");
        }
        e.requested = e.written = e.resetAfterRequest = false;
    }
    ++frame_;
}

void HistoryStore::trim(uint32_t unusedFrames) {
    for (auto it = entries_.begin(); it != entries_.end();) {
        Entry& e = it->second;
        if (e.requested || e.lastRequestedFrame + unusedFrames >= frame_) {
            ++it;
            continue;
        }
        release(e);
        it = entries_.erase(it);
    }
}

// ---- resets --------------------------------------------------------------------------------------

void HistoryStore::resetEntry(const std::string& name, Entry& e, const std::string& reason) {
    e.previousValid = false;
    // This frame's pass already got the pre-reset history, so what it writes is tainted too.
    if (e.requested) e.resetAfterRequest = true;
    ++e.status.resets;
    e.status.lastResetReason = reason;
    e.status.lastResetFrame = frame_;
    if (log_.size() >= kMaxLogLines) log_.erase(log_.begin());
    log_.push_back(label(name) + " reset: " + reason);
}

void HistoryStore::reset(const std::string& name, const std::string& reason) {
    auto it = entries_.find(name);
    if (it == entries_.end()) fail("reset of unknown " + label(name) + " (" + reason + ")");
    resetEntry(name, it->second, reason);
}

void HistoryStore::resetAll(const std::string& reason) {
    for (auto& [name, e] : entries_) resetEntry(name, e, reason);
}

// ---- introspection -------------------------------------------------------------------------------

std::optional<HistoryStatus> HistoryStore::status(const std::string& name) const {
    auto it = entries_.find(name);
    if (it == entries_.end()) return std::nullopt;
    HistoryStatus s = it->second.status;
    s.isImage = it->second.isImage;
    s.previousValid = it->second.previousValid;
    return s;
}

const HistoryStore::Entry& HistoryStore::find(const std::string& name, bool isImage) const {
    auto it = entries_.find(name);
    if (it == entries_.end()) fail("no " + label(name));
    if (it->second.isImage != isImage) fail(label(name) + " is not " + (isImage ? "an image" : "a buffer"));
    return it->second;
}

const ExternalImage& HistoryStore::previousImage(const std::string& name) const {
    const Entry& e = find(name, true);
    return e.images[1 - e.current];
}
const ExternalImage& HistoryStore::currentImage(const std::string& name) const {
    const Entry& e = find(name, true);
    return e.images[e.current];
}
const ExternalBuffer& HistoryStore::previousBuffer(const std::string& name) const {
    const Entry& e = find(name, false);
    return e.buffers[1 - e.current];
}
const ExternalBuffer& HistoryStore::currentBuffer(const std::string& name) const {
    const Entry& e = find(name, false);
    return e.buffers[e.current];
}

// ---- RenderGraph side ----------------------------------------------------------------------------

// The pair enters the graph as two imports named "<name>[previous]" / "<name>[current]", so errors,
// timings and the Graphviz dump say which half a pass got wrong.
HistoryImage RenderGraph::history(HistoryStore& store, const std::string& name, const ImageDesc& desc) {
    HistoryStore::Pair<ExternalImage> pair = store.requestImage(name, desc);
    HistoryImage h;
    h.previous = importImage(name + "[previous]", pair.previous);
    h.current = importImage(name + "[current]", pair.current);
    h.previousValid = pair.previousValid;
    histories_.push_back({&store, name, h.current.id});
    return h;
}

HistoryBuffer RenderGraph::history(HistoryStore& store, const std::string& name, const BufferDesc& desc) {
    HistoryStore::Pair<ExternalBuffer> pair = store.requestBuffer(name, desc);
    HistoryBuffer h;
    h.previous = importBuffer(name + "[previous]", pair.previous);
    h.current = importBuffer(name + "[current]", pair.current);
    h.previousValid = pair.previousValid;
    histories_.push_back({&store, name, h.current.id});
    return h;
}

}  // namespace ppr::graph
