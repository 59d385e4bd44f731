#pragma once
// Render graph: passes declare *what* they touch through purpose-named verbs during setup; the graph
// orders them, culls passes nobody consumes, derives usage flags, and plans every barrier as plain
// data (testable without a GPU). GraphExecutor (executor.hpp) turns the plan into Vulkan commands.
//
// Handles are typed and versioned: every write returns a new version and the old one goes stale, so a
// pass cannot accidentally read a resource "before" another pass's write.
#include "graph/access.hpp"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ppr::graph {

struct ImageDesc {
    uint32_t width = 0;
    uint32_t height = 0;
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t mipLevels = 1;
    bool operator==(const ImageDesc&) const = default;
};

struct BufferDesc {
    VkDeviceSize size = 0;
    bool operator==(const BufferDesc&) const = default;
};

struct ImageTag {};
struct BufferTag {};

template <class Tag>
struct Handle {
    uint32_t id = UINT32_MAX;  // index of the logical resource
    uint32_t version = 0;      // bumped by every write
    bool valid() const { return id != UINT32_MAX; }
    bool operator==(const Handle&) const = default;
};
using ImageHandle = Handle<ImageTag>;
using BufferHandle = Handle<BufferTag>;

bool isDepthFormat(VkFormat format);

// State a resource is in outside the graph: last write (or layout transition) and its layout.
struct ResourceState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// A resource owned outside the graph (swapchain image, history, read-back buffer). The graph reads
// `state` as the starting point and writes the state it left the resource in back after execution.
// `finalAccess`, when set, makes the graph transition the resource there at the end of the frame
// (Present for a swapchain image, HostRead for a read-back buffer).
struct ExternalImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    ImageDesc desc;
    ResourceState state;
    std::optional<Access> finalAccess;
};
struct ExternalBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    BufferDesc desc;
    ResourceState state;
    std::optional<Access> finalAccess;
};

enum class LoadOp : uint8_t { Load, Clear, DontCare };

struct AttachmentInfo {
    ImageHandle image;
    LoadOp load = LoadOp::Load;
    VkClearValue clear{};
};

// One barrier the graph will record, as plain data.
struct PlannedBarrier {
    uint32_t resource = 0;  // logical resource id
    bool isImage = true;
    VkPipelineStageFlags2 srcStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 srcAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 dstStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 dstAccess = VK_ACCESS_2_NONE;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout newLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    bool operator==(const PlannedBarrier&) const = default;
};

struct ResourceUse {
    uint32_t resource = 0;
    bool isImage = true;
    Access access = Access::Sampled;
    uint32_t versionRead = 0;     // version consumed (0 = contents not needed)
    uint32_t versionWritten = 0;  // version produced (0 = no write)
};

class PassContext;
class RenderGraph;
class HistoryStore;

// One frame's view of a history entry (history.hpp): read `previous` (last frame's contents, only
// meaningful when previousValid), write `current` (becomes `previous` next frame).
struct HistoryImage {
    ImageHandle previous;
    ImageHandle current;
    bool previousValid = false;  // false on the first frame after creation or a reset
};
struct HistoryBuffer {
    BufferHandle previous;
    BufferHandle current;
    bool previousValid = false;
};

class PassBuilder {
public:
    // Images
    ImageHandle sampled(ImageHandle h);
    ImageHandle storageRead(ImageHandle h);
    ImageHandle storageWrite(ImageHandle h);      // returns the new version
    ImageHandle storageReadWrite(ImageHandle h);  // returns the new version
    ImageHandle colorAttachment(ImageHandle h, LoadOp load = LoadOp::Load, VkClearColorValue clear = {});
    ImageHandle depthAttachment(ImageHandle h, LoadOp load = LoadOp::Load, float clearDepth = 0.0f);
    ImageHandle depthAttachmentRead(ImageHandle h);
    ImageHandle transferSrc(ImageHandle h);
    ImageHandle transferDst(ImageHandle h);  // returns the new version
    // Buffers
    BufferHandle storageRead(BufferHandle h);
    BufferHandle storageWrite(BufferHandle h);
    BufferHandle storageReadWrite(BufferHandle h);
    BufferHandle uniformRead(BufferHandle h);
    BufferHandle vertexRead(BufferHandle h);
    // An acceleration structure's storage (or a build's scratch) as a build writes it / a ray query reads it.
    BufferHandle accelerationStructureBuild(BufferHandle h);
    BufferHandle accelerationStructureRead(BufferHandle h);
    BufferHandle indirectArgs(BufferHandle h);  // pairs with PassContext::dispatchIndirect
    BufferHandle transferSrc(BufferHandle h);
    BufferHandle transferDst(BufferHandle h);
    // Never cull this pass (present, capture, read-back, anything observable outside the graph).
    void sideEffect();
    // Graphics pass that begins its own VkRenderPass (e.g. the ImGui 1.86 backend) instead of the
    // graph's dynamic rendering over the declared attachments.
    void customRendering();

private:
    friend class RenderGraph;
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
    RenderGraph& graph_;
    uint32_t pass_;
};

class PassContext {
public:
    VkCommandBuffer cmd() const { return cmd_; }
    VkImage image(ImageHandle h) const;
    VkImageView view(ImageHandle h) const;
    const ImageDesc& desc(ImageHandle h) const;
    VkImageLayout layout(ImageHandle h) const;  // the layout this pass declared for h
    VkBuffer buffer(BufferHandle h) const;
    VkDeviceSize size(BufferHandle h) const;
    VkExtent2D renderExtent() const;  // extent of the attachments (graphics passes)
    // vkCmdDispatchIndirect on a buffer this pass declared with indirectArgs(); throws otherwise.
    void dispatchIndirect(BufferHandle args, VkDeviceSize offset = 0) const;

private:
    friend class GraphExecutor;
    PassContext(const RenderGraph& g, uint32_t pass, VkCommandBuffer cmd) : graph_(g), pass_(pass), cmd_(cmd) {}
    const RenderGraph& graph_;
    uint32_t pass_;
    VkCommandBuffer cmd_;
};

struct CompiledPass {
    std::string name;
    uint32_t index = 0;  // declaration index
    QueueKind kind = QueueKind::Graphics;
    bool culled = false;
    std::vector<PlannedBarrier> barriers;  // recorded in one vkCmdPipelineBarrier2 before the pass
};

class RenderGraph {
public:
    RenderGraph() = default;
    RenderGraph(const RenderGraph&) = delete;
    RenderGraph& operator=(const RenderGraph&) = delete;

    // Transient resources: created lazily from the executor's pool; contents undefined at first use.
    ImageHandle createImage(std::string name, const ImageDesc& desc);
    BufferHandle createBuffer(std::string name, const BufferDesc& desc);
    // Imported resources: the pointee must outlive execution; the graph updates its state.
    ImageHandle importImage(std::string name, ExternalImage* image);
    BufferHandle importBuffer(std::string name, ExternalBuffer* buffer);
    // History resources (history.hpp): the store's ping-pong pair for `name`, imported as
    // "<name>[previous]" and "<name>[current]". A changed descriptor reallocates and resets the entry.
    // Like imports, the store must outlive this graph's execution.
    HistoryImage history(HistoryStore& store, const std::string& name, const ImageDesc& desc);
    HistoryBuffer history(HistoryStore& store, const std::string& name, const BufferDesc& desc);

    template <class Data>
    const Data& addPass(std::string name, QueueKind kind, const std::function<void(PassBuilder&, Data&)>& setup,
                        std::function<void(const Data&, PassContext&)> execute) {
        auto pass = std::make_unique<TypedPass<Data>>();
        uint32_t index = beginPass(std::move(name), kind);
        PassBuilder builder(*this, index);
        setup(builder, pass->data);
        pass->execute = std::move(execute);
        Data& data = pass->data;
        passes_[index].body = std::move(pass);
        return data;
    }

    // Orders, culls, derives usage and plans barriers. Throws std::runtime_error naming the pass and
    // resource on misuse (stale handle, read of a never-written resource, double declaration...).
    void compile();

    // Results of compile(), for the executor, tests and tools.
    const std::vector<CompiledPass>& compiledPasses() const { return compiled_; }
    const std::vector<PlannedBarrier>& finalBarriers() const { return finalBarriers_; }  // to imports' finalAccess
    std::vector<std::string> culledPasses() const;
    std::string cullLog() const;  // "graph: culled pass 'x' (nothing reads: a, b)" lines, empty if none
    std::string toDot() const;    // Graphviz of passes and resource versions (culled passes dashed)

    // After the frame's commands are recorded: writes each import's end state back into its
    // ExternalImage/ExternalBuffer and tells history stores which `current` a kept pass wrote.
    // GraphExecutor::execute calls it; GPU-free so tests can simulate frames with it.
    void commitImportStates();

    // Resource introspection.
    uint32_t resourceCount() const { return static_cast<uint32_t>(resources_.size()); }
    const std::string& resourceName(uint32_t id) const { return resources_[id].name; }
    bool isImported(uint32_t id) const { return resources_[id].importedImage || resources_[id].importedBuffer; }
    VkImageUsageFlags imageUsage(uint32_t id) const { return resources_[id].imageUsage; }    // derived
    VkBufferUsageFlags bufferUsage(uint32_t id) const { return resources_[id].bufferUsage; }  // derived
    uint32_t resourceId(const std::string& name) const;  // throws if unknown
    const ImageDesc& imageDesc(ImageHandle h) const;     // throws on a handle this graph did not make
    const std::vector<ResourceUse>& passUses(uint32_t pass) const { return passes_[pass].uses; }

private:
    friend class PassBuilder;
    friend class PassContext;
    friend class GraphExecutor;

    struct PassBody {
        virtual ~PassBody() = default;
        virtual void run(PassContext& ctx) const = 0;
    };
    template <class Data>
    struct TypedPass final : PassBody {
        Data data{};
        std::function<void(const Data&, PassContext&)> execute;
        void run(PassContext& ctx) const override {
            if (execute) execute(data, ctx);
        }
    };

    struct Resource {
        std::string name;
        bool isImage = true;
        ImageDesc imageDesc;
        BufferDesc bufferDesc;
        ExternalImage* importedImage = nullptr;
        ExternalBuffer* importedBuffer = nullptr;
        uint32_t version = 0;  // latest version produced during setup
        VkImageUsageFlags imageUsage = 0;
        VkBufferUsageFlags bufferUsage = 0;
        // Filled by the executor: the physical objects for this frame.
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkBuffer buffer = VK_NULL_HANDLE;
    };

    struct Pass {
        std::string name;
        QueueKind kind = QueueKind::Graphics;
        std::unique_ptr<PassBody> body;
        std::vector<ResourceUse> uses;
        std::vector<AttachmentInfo> colorAttachments;
        std::optional<AttachmentInfo> depthAttachment;
        bool depthReadOnly = false;
        bool sideEffect = false;
        bool customRendering = false;
    };

    uint32_t addResource(Resource r);  // checks the name is unique; returns the id
    uint32_t beginPass(std::string name, QueueKind kind);
    uint32_t declare(uint32_t pass, uint32_t resource, uint32_t version, bool isImage, Access access);
    const Resource& resourceFor(uint32_t pass, uint32_t id, bool isImage) const;
    // True when the use needs the resource's previous contents (reads, read-modify-write, LoadOp::Load).
    bool readsContents(const Pass& pass, const ResourceUse& use) const;
    // compile() steps (compile.cpp, barrier_plan.cpp).
    void cull();
    void deriveUsage();
    void planBarriers();

    std::vector<Resource> resources_;
    std::vector<Pass> passes_;
    std::vector<CompiledPass> compiled_;
    std::vector<PlannedBarrier> finalBarriers_;
    std::vector<ResourceState> endStates_;  // per resource after the frame; the executor writes it to imports
    struct HistoryUse {
        HistoryStore* store;
        std::string name;
        uint32_t current;  // resource id of the entry's `current` import
    };
    std::vector<HistoryUse> histories_;
    bool compiled = false;
};

}  // namespace ppr::graph
