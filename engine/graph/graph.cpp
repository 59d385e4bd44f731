// RenderGraph setup: resources, passes and the builder verbs. Every misuse is caught here, while the
// pass that made it is still being declared, and the message names that pass and the resource.
#include "graph/graph.hpp"

#include <stdexcept>

namespace ppr::graph {

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error("graph: " + message); }

// Names identify resources in errors, logs, timings and resourceId(), so they must be unique.
template <class Resources>
void checkUniqueName(const Resources& resources, const std::string& name) {
    for (const auto& r : resources)
        if (r.name == name) fail("resource '" + name + "' is declared twice");
}

bool isAttachment(Access a) {
    return a == Access::ColorAttachment || a == Access::DepthAttachment || a == Access::DepthAttachmentRead;
}

}  // namespace

// ---- resources -----------------------------------------------------------------------------------

uint32_t RenderGraph::addResource(Resource r) {
    checkUniqueName(resources_, r.name);
    resources_.push_back(std::move(r));
    return static_cast<uint32_t>(resources_.size() - 1);
}

ImageHandle RenderGraph::createImage(std::string name, const ImageDesc& desc) {
    if (desc.width == 0 || desc.height == 0 || desc.format == VK_FORMAT_UNDEFINED || desc.mipLevels == 0)
        fail("image '" + name + "' has an empty extent, no mip level or an undefined format");
    Resource r;
    r.name = std::move(name);
    r.imageDesc = desc;
    return {addResource(std::move(r)), 0};
}

BufferHandle RenderGraph::createBuffer(std::string name, const BufferDesc& desc) {
    if (desc.size == 0) fail("buffer '" + name + "' has size 0");
    Resource r;
    r.name = std::move(name);
    r.isImage = false;
    r.bufferDesc = desc;
    return {addResource(std::move(r)), 0};
}

ImageHandle RenderGraph::importImage(std::string name, ExternalImage* image) {
    if (!image) fail("importImage('" + name + "') got a null ExternalImage");
    Resource r;
    r.name = std::move(name);
    r.imageDesc = image->desc;
    r.importedImage = image;
    return {addResource(std::move(r)), 0};
}

BufferHandle RenderGraph::importBuffer(std::string name, ExternalBuffer* buffer) {
    if (!buffer) fail("importBuffer('" + name + "') got a null ExternalBuffer");
    Resource r;
    r.name = std::move(name);
    r.isImage = false;
    r.bufferDesc = buffer->desc;
    r.importedBuffer = buffer;
    return {addResource(std::move(r)), 0};
}

uint32_t RenderGraph::resourceId(const std::string& name) const {
    for (uint32_t i = 0; i < resources_.size(); ++i)
        if (resources_[i].name == name) return i;
    fail("no resource named '" + name + "'");
}

const ImageDesc& RenderGraph::imageDesc(ImageHandle h) const {
    if (h.id >= resources_.size() || !resources_[h.id].isImage) fail("imageDesc: not an image handle of this graph");
    return resources_[h.id].imageDesc;
}

// ---- passes --------------------------------------------------------------------------------------

uint32_t RenderGraph::beginPass(std::string name, QueueKind kind) {
    for (const Pass& p : passes_)
        if (p.name == name) fail("pass '" + name + "' is declared twice");
    Pass p;
    p.name = std::move(name);
    p.kind = kind;
    passes_.push_back(std::move(p));
    compiled = false;  // a new pass invalidates the previous plan
    return static_cast<uint32_t>(passes_.size() - 1);
}

bool RenderGraph::readsContents(const Pass& pass, const ResourceUse& use) const {
    switch (use.access) {
        case Access::ColorAttachment:
            for (const AttachmentInfo& a : pass.colorAttachments)
                if (a.image.id == use.resource) return a.load == LoadOp::Load;
            return true;
        case Access::DepthAttachment:
            return !pass.depthAttachment || pass.depthAttachment->load == LoadOp::Load;
        case Access::StorageReadWrite: return true;
        default: return !isWrite(use.access);
    }
}

uint32_t RenderGraph::declare(uint32_t passIndex, uint32_t resource, uint32_t version, bool isImage, Access access) {
    Pass& pass = passes_[passIndex];
    const std::string where = "pass '" + pass.name + "' ";
    if (resource >= resources_.size() || resources_[resource].isImage != isImage)
        fail(where + "uses an invalid " + (isImage ? "image" : "buffer") + " handle (" + accessName(access) + ")");
    Resource& r = resources_[resource];
    const std::string what = where + "uses '" + r.name + "'";

    for (const ResourceUse& u : pass.uses)
        if (u.resource == resource)
            fail(where + "declares '" + r.name + "' twice (" + accessName(u.access) + " and " + accessName(access) +
                 ")");
    if (version != r.version)
        fail(where + "uses stale handle of '" + r.name + "' (version " + std::to_string(version) + ", latest " +
             std::to_string(r.version) + ")");

    if (isAttachment(access)) {
        if (pass.kind != QueueKind::Graphics) fail(what + " as " + accessName(access) + " outside a graphics pass");
        const bool depth = isDepthFormat(r.imageDesc.format);
        if (depth != (access != Access::ColorAttachment))
            fail(what + " as " + accessName(access) + " but its format is " + (depth ? "" : "not ") + "a depth format");
        // Dynamic rendering needs one render area: all attachments of a pass share the first one's extent.
        const AttachmentInfo* first = !pass.colorAttachments.empty() ? &pass.colorAttachments.front()
                                      : pass.depthAttachment                ? &*pass.depthAttachment
                                                                            : nullptr;
        if (first && first->image.id != resource) {
            const ImageDesc& d = resources_[first->image.id].imageDesc;
            if (d.width != r.imageDesc.width || d.height != r.imageDesc.height)
                fail(what + " as an attachment but its extent differs from '" + resources_[first->image.id].name +
                     "'");
        }
    }

    ResourceUse use;
    use.resource = resource;
    use.isImage = isImage;
    use.access = access;
    if (readsContents(pass, use)) {
        if (version == 0 && !isImported(resource))
            fail(where + "reads '" + r.name + "' before any pass wrote it");
        use.versionRead = version;
    }
    if (isWrite(access)) use.versionWritten = ++r.version;
    pass.uses.push_back(use);
    return r.version;
}

// ---- builder verbs -------------------------------------------------------------------------------

namespace {
template <class H>
H next(H h, uint32_t version) {
    return {h.id, version};
}
}  // namespace

ImageHandle PassBuilder::sampled(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::Sampled)); }
ImageHandle PassBuilder::storageRead(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::StorageRead)); }
ImageHandle PassBuilder::storageWrite(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::StorageWrite)); }
ImageHandle PassBuilder::storageReadWrite(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::StorageReadWrite)); }
ImageHandle PassBuilder::transferSrc(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::TransferSrc)); }
ImageHandle PassBuilder::transferDst(ImageHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, true, Access::TransferDst)); }

// Attachments are recorded before declare() so it can see the load op (Load reads, Clear does not);
// on error they are removed again so a caught exception leaves the pass as it was.
ImageHandle PassBuilder::colorAttachment(ImageHandle h, LoadOp load, VkClearColorValue clear) {
    auto& pass = graph_.passes_[pass_];
    AttachmentInfo info{h, load, {}};
    info.clear.color = clear;
    pass.colorAttachments.push_back(info);
    try {
        ImageHandle out = next(h, graph_.declare(pass_, h.id, h.version, true, Access::ColorAttachment));
        pass.colorAttachments.back().image = out;
        return out;
    } catch (...) {
        pass.colorAttachments.pop_back();
        throw;
    }
}

ImageHandle PassBuilder::depthAttachment(ImageHandle h, LoadOp load, float clearDepth) {
    auto& pass = graph_.passes_[pass_];
    if (pass.depthAttachment)
        fail("pass '" + pass.name + "' declares a second depth attachment ('" + graph_.resourceName(h.id) + "')");
    AttachmentInfo info{h, load, {}};
    info.clear.depthStencil = {clearDepth, 0};
    pass.depthAttachment = info;
    try {
        ImageHandle out = next(h, graph_.declare(pass_, h.id, h.version, true, Access::DepthAttachment));
        pass.depthAttachment->image = out;
        return out;
    } catch (...) {
        pass.depthAttachment.reset();
        throw;
    }
}

ImageHandle PassBuilder::depthAttachmentRead(ImageHandle h) {
    auto& pass = graph_.passes_[pass_];
    if (pass.depthAttachment)
        fail("pass '" + pass.name + "' declares a second depth attachment ('" + graph_.resourceName(h.id) + "')");
    pass.depthAttachment = AttachmentInfo{h, LoadOp::Load, {}};
    pass.depthReadOnly = true;
    try {
        return next(h, graph_.declare(pass_, h.id, h.version, true, Access::DepthAttachmentRead));
    } catch (...) {
        pass.depthAttachment.reset();
        pass.depthReadOnly = false;
        throw;
    }
}

BufferHandle PassBuilder::storageRead(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::StorageRead)); }
BufferHandle PassBuilder::storageWrite(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::StorageWrite)); }
BufferHandle PassBuilder::storageReadWrite(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::StorageReadWrite)); }
BufferHandle PassBuilder::uniformRead(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::UniformRead)); }
BufferHandle PassBuilder::vertexRead(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::VertexRead)); }
BufferHandle PassBuilder::accelerationStructureBuild(BufferHandle h) {
    return next(h, graph_.declare(pass_, h.id, h.version, false, Access::AccelerationStructureBuild));
}
BufferHandle PassBuilder::accelerationStructureRead(BufferHandle h) {
    return next(h, graph_.declare(pass_, h.id, h.version, false, Access::AccelerationStructureRead));
}
BufferHandle PassBuilder::indirectArgs(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::IndirectArgs)); }
BufferHandle PassBuilder::transferSrc(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::TransferSrc)); }
BufferHandle PassBuilder::transferDst(BufferHandle h) { return next(h, graph_.declare(pass_, h.id, h.version, false, Access::TransferDst)); }

void PassBuilder::sideEffect() { graph_.passes_[pass_].sideEffect = true; }

void PassBuilder::customRendering() {
    auto& pass = graph_.passes_[pass_];
    if (pass.kind != QueueKind::Graphics) fail("pass '" + pass.name + "' asks for customRendering() but is not a graphics pass");
    pass.customRendering = true;
}

}  // namespace ppr::graph
