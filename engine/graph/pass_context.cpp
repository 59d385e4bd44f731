// PassContext: what a pass body may ask about its own declared resources while recording. Asking for
// a resource the pass did not declare throws, so an undeclared access can never slip past barriers.
#include "graph/graph.hpp"

#include <stdexcept>

namespace ppr::graph {

namespace {
const ResourceUse* findUse(const std::vector<ResourceUse>& uses, uint32_t resource) {
    for (const ResourceUse& u : uses)
        if (u.resource == resource) return &u;
    return nullptr;
}
}  // namespace

const RenderGraph::Resource& RenderGraph::resourceFor(uint32_t pass, uint32_t id, bool isImage) const {
    const Pass& p = passes_[pass];
    if (id >= resources_.size() || resources_[id].isImage != isImage)
        throw std::runtime_error("graph: pass '" + p.name + "' asks for an invalid " +
                                 (isImage ? "image" : "buffer") + " handle");
    if (!findUse(p.uses, id))
        throw std::runtime_error("graph: pass '" + p.name + "' uses '" + resources_[id].name +
                                 "' without declaring it in setup");
    return resources_[id];
}

VkImage PassContext::image(ImageHandle h) const { return graph_.resourceFor(pass_, h.id, true).image; }
VkImageView PassContext::view(ImageHandle h) const { return graph_.resourceFor(pass_, h.id, true).view; }
const ImageDesc& PassContext::desc(ImageHandle h) const { return graph_.resourceFor(pass_, h.id, true).imageDesc; }
VkBuffer PassContext::buffer(BufferHandle h) const { return graph_.resourceFor(pass_, h.id, false).buffer; }
VkDeviceSize PassContext::size(BufferHandle h) const { return graph_.resourceFor(pass_, h.id, false).bufferDesc.size; }

VkImageLayout PassContext::layout(ImageHandle h) const {
    const RenderGraph::Resource& r = graph_.resourceFor(pass_, h.id, true);
    const auto& pass = graph_.passes_[pass_];
    return accessInfo(findUse(pass.uses, h.id)->access, pass.kind, isDepthFormat(r.imageDesc.format)).layout;
}

VkExtent2D PassContext::renderExtent() const {
    const auto& pass = graph_.passes_[pass_];
    const AttachmentInfo* first = !pass.colorAttachments.empty() ? &pass.colorAttachments.front()
                                  : pass.depthAttachment                ? &*pass.depthAttachment
                                                                        : nullptr;
    if (!first) throw std::runtime_error("graph: pass '" + pass.name + "' asks for renderExtent() but has no attachments");
    const ImageDesc& d = graph_.resources_[first->image.id].imageDesc;
    return {d.width, d.height};
}

void PassContext::dispatchIndirect(BufferHandle args, VkDeviceSize offset) const {
    const RenderGraph::Resource& r = graph_.resourceFor(pass_, args.id, false);
    const auto& pass = graph_.passes_[pass_];
    if (findUse(pass.uses, args.id)->access != Access::IndirectArgs)
        throw std::runtime_error("graph: pass '" + pass.name + "' calls dispatchIndirect on '" + r.name +
                                 "' without declaring indirectArgs() for it");
    vkCmdDispatchIndirect(cmd_, r.buffer, offset);
}

}  // namespace ppr::graph
