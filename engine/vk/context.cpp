#include "vk/context.hpp"

#include "util/process_heap.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace ppr::vk {
namespace {

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasInstanceExtension(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

bool hasDeviceExtension(VkPhysicalDevice dev, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(dev, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateDeviceExtensionProperties(dev, nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* counters = static_cast<ValidationCounters*>(user);
    if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) {
        counters->errors++;
        std::fprintf(stderr, "validation error: %s\n", data->pMessage);
    } else if (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
        counters->warnings++;
        std::fprintf(stderr, "validation warning: %s\n", data->pMessage);
    }
    return VK_FALSE;
}

const char* deviceTypeName(VkPhysicalDeviceType t) {
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual";
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        default: return "other";
    }
}

int deviceRank(VkPhysicalDeviceType t, bool preferSoftware) {
    if (preferSoftware) return t == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0 : 1;
    switch (t) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
        default: return 4;
    }
}

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

}  // namespace

std::unique_ptr<Context> Context::create(const ContextOptions& options) {
    std::unique_ptr<Context> ctx(new Context());
    ctx->validation_ = options.validation || envFlag("PPR_VALIDATION");
    const bool preferSoftware = options.preferSoftware || (std::getenv("PPR_DEVICE") && std::string(std::getenv("PPR_DEVICE")) == "cpu");

    std::vector<const char*> layers;
    std::vector<const char*> extensions = options.instanceExtensions;
    if (ctx->validation_) {
        if (!hasLayer(kValidationLayer))
            throw std::runtime_error("vulkan: --validation requested but VK_LAYER_KHRONOS_validation is not installed (apt-get install vulkan-validationlayers)");
        layers.push_back(kValidationLayer);
    }
    ctx->debugUtils_ = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (ctx->debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ppr";
    app.pEngineName = "ppr";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = debugCallback;
    messengerInfo.pUserData = ctx->counters_.get();

    // Synchronization validation is off by default in the layer; switch it on explicitly.
    VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;

    VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    ici.enabledLayerCount = static_cast<uint32_t>(layers.size());
    ici.ppEnabledLayerNames = layers.data();
    ici.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    ici.ppEnabledExtensionNames = extensions.data();
    if (ctx->validation_) {
        features.pNext = ctx->debugUtils_ ? &messengerInfo : nullptr;
        ici.pNext = &features;
    }
    VK_CHECK(vkCreateInstance(&ici, nullptr, &ctx->instance_));

    if (ctx->debugUtils_) {
        auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (ctx->validation_ && createMessenger) VK_CHECK(createMessenger(ctx->instance_, &messengerInfo, nullptr, &ctx->messenger_));
        ctx->setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkSetDebugUtilsObjectNameEXT"));
        ctx->beginLabel_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkCmdBeginDebugUtilsLabelEXT"));
        ctx->endLabel_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkCmdEndDebugUtilsLabelEXT"));
    }

    // Pick the best device that has Vulkan 1.3, push descriptors and a graphics+compute queue.
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(ctx->instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(ctx->instance_, &count, devices.data());
    int bestRank = 1 << 30;
    std::string rejected;
    for (VkPhysicalDevice dev : devices) {
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(dev, &props);
        std::string why;
        if (props.apiVersion < VK_API_VERSION_1_3) why = "Vulkan < 1.3";
        else if (!hasDeviceExtension(dev, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) why = "no VK_KHR_push_descriptor";
        else if (options.swapchain && !hasDeviceExtension(dev, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) why = "no VK_KHR_swapchain";
        if (!why.empty()) {
            rejected += std::string(" ") + props.deviceName + " (" + why + ");";
            continue;
        }
        int rank = deviceRank(props.deviceType, preferSoftware);
        if (rank < bestRank) {
            bestRank = rank;
            ctx->physical_ = dev;
        }
    }
    if (!ctx->physical_)
        throw std::runtime_error("vulkan: no suitable device (need Vulkan 1.3 + VK_KHR_push_descriptor);" + rejected +
                                 " install mesa-vulkan-drivers from bookworm-backports for lavapipe");

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(ctx->physical_, &props);
    VkPhysicalDeviceVulkan11Properties props11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
    VkPhysicalDeviceDriverProperties driverProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    driverProps.pNext = &props11;
    VkPhysicalDeviceProperties2 props2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props2.pNext = &driverProps;
    vkGetPhysicalDeviceProperties2(ctx->physical_, &props2);
    ctx->info_.name = props.deviceName;
    ctx->info_.type = deviceTypeName(props.deviceType);
    ctx->info_.driver = std::string(driverProps.driverName) + " " + driverProps.driverInfo;
    ctx->info_.apiVersion = props.apiVersion;
    ctx->info_.apiVersionString = std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
                                  std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
                                  std::to_string(VK_API_VERSION_PATCH(props.apiVersion));
    ctx->info_.timestampPeriodNs = props.limits.timestampPeriod;
    ctx->info_.subPixelPrecisionBits = props.limits.subPixelPrecisionBits;
    ctx->info_.subgroupSize = props11.subgroupSize;
    if (props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && !util::heapTunedByUser(std::getenv("GLIBC_TUNABLES")))
        ctx->info_.heapKept = util::keepFreedHeapMemory();

    // One queue family that does graphics + compute (+ transfer implicitly).
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_, &familyCount, families.data());
    bool found = false;
    for (uint32_t i = 0; i < familyCount; ++i) {
        if ((families[i].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) == (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT) &&
            families[i].timestampValidBits > 0) {
            ctx->queueFamily_ = i;
            ctx->info_.timestampValidBits = families[i].timestampValidBits;
            found = true;
            break;
        }
    }
    if (!found) throw std::runtime_error("vulkan: " + ctx->info_.name + " has no graphics+compute queue with timestamps");

    // Ray queries (optional: only the `raytraced` reference needs them). All or nothing.
    RayQuerySupport& rq = ctx->rayQuery_;
    rq.hidden = envFlag("PPR_HIDE_RAY_QUERY");
    const char* const rayExtensions[] = {VK_KHR_RAY_QUERY_EXTENSION_NAME, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME,
                                         VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};
    for (const char* e : rayExtensions)
        if (rq.hidden || !hasDeviceExtension(ctx->physical_, e)) rq.missing += (rq.missing.empty() ? "" : ", ") + std::string(e);
    VkPhysicalDeviceRayQueryFeaturesKHR rayQueryFeatures{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
    VkPhysicalDeviceAccelerationStructureFeaturesKHR accelFeatures{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR};
    accelFeatures.pNext = &rayQueryFeatures;
    if (rq.missing.empty()) {
        VkPhysicalDeviceVulkan12Features s12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        s12.pNext = &accelFeatures;
        VkPhysicalDeviceFeatures2 s2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        s2.pNext = &s12;
        vkGetPhysicalDeviceFeatures2(ctx->physical_, &s2);
        if (!rayQueryFeatures.rayQuery) rq.missing = "the rayQuery feature";
        else if (!accelFeatures.accelerationStructure) rq.missing = "the accelerationStructure feature";
        else if (!s12.bufferDeviceAddress) rq.missing = "the bufferDeviceAddress feature";
        // Only what the reference uses: no capture/replay, indirect builds or host commands.
        accelFeatures = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_FEATURES_KHR, &rayQueryFeatures};
        accelFeatures.accelerationStructure = VK_TRUE;
        rayQueryFeatures = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_RAY_QUERY_FEATURES_KHR};
        rayQueryFeatures.rayQuery = VK_TRUE;
    }
    rq.available = rq.missing.empty();

    // Features the renderer relies on (all supported by lavapipe on Mesa 25 and by desktop GPUs).
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.synchronization2 = VK_TRUE;
    f13.dynamicRendering = VK_TRUE;
    f13.maintenance4 = VK_TRUE;  // glslang --target-env vulkan1.3 emits LocalSizeId
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    f12.pNext = &f13;
    f12.descriptorIndexing = VK_TRUE;
    f12.runtimeDescriptorArray = VK_TRUE;
    f12.shaderSampledImageArrayNonUniformIndexing = VK_TRUE;
    f12.descriptorBindingPartiallyBound = VK_TRUE;
    f12.scalarBlockLayout = VK_TRUE;
    f12.hostQueryReset = VK_TRUE;
    f12.separateDepthStencilLayouts = VK_TRUE;  // DEPTH_ATTACHMENT_OPTIMAL / DEPTH_READ_ONLY_OPTIMAL
    if (rq.available) {
        f12.bufferDeviceAddress = VK_TRUE;  // acceleration-structure build inputs and scratch
        f13.pNext = &accelFeatures;
    }
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f12;
    f2.features.samplerAnisotropy = VK_TRUE;
    f2.features.fragmentStoresAndAtomics = VK_TRUE;
    f2.features.shaderStorageImageWriteWithoutFormat = VK_TRUE;
    f2.features.shaderStorageImageReadWithoutFormat = VK_TRUE;
    f2.features.depthClamp = VK_TRUE;
    f2.features.dualSrcBlend = VK_TRUE;  // the glass pass: add the reflection, filter what shows through

    // Check support so a missing feature gives a clear message instead of VK_ERROR_FEATURE_NOT_PRESENT.
    {
        VkPhysicalDeviceVulkan13Features s13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        VkPhysicalDeviceVulkan12Features s12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
        s12.pNext = &s13;
        VkPhysicalDeviceFeatures2 s2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        s2.pNext = &s12;
        vkGetPhysicalDeviceFeatures2(ctx->physical_, &s2);
        std::string missing;
        auto need = [&](VkBool32 have, const char* what) {
            if (!have) missing += std::string(" ") + what;
        };
        need(s13.synchronization2, "synchronization2");
        need(s13.dynamicRendering, "dynamicRendering");
        need(s13.maintenance4, "maintenance4");
        need(s12.runtimeDescriptorArray, "runtimeDescriptorArray");
        need(s12.shaderSampledImageArrayNonUniformIndexing, "shaderSampledImageArrayNonUniformIndexing");
        need(s12.descriptorBindingPartiallyBound, "descriptorBindingPartiallyBound");
        need(s12.scalarBlockLayout, "scalarBlockLayout");
        need(s12.hostQueryReset, "hostQueryReset");
        need(s12.separateDepthStencilLayouts, "separateDepthStencilLayouts");
        need(s2.features.fragmentStoresAndAtomics, "fragmentStoresAndAtomics");
        need(s2.features.shaderStorageImageWriteWithoutFormat, "shaderStorageImageWriteWithoutFormat");
        need(s2.features.shaderStorageImageReadWithoutFormat, "shaderStorageImageReadWithoutFormat");
        need(s2.features.dualSrcBlend, "dualSrcBlend");
        // Tile classification and the projection reduce with subgroup operations (one shared atomic per subgroup).
        VkPhysicalDeviceVulkan11Properties p11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES};
        VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        p2.pNext = &p11;
        vkGetPhysicalDeviceProperties2(ctx->physical_, &p2);
        const VkSubgroupFeatureFlags subgroupOps = VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
        need((p11.subgroupSupportedStages & VK_SHADER_STAGE_COMPUTE_BIT) && (p11.subgroupSupportedOperations & subgroupOps) == subgroupOps,
             "subgroup basic+arithmetic operations in compute shaders");
        if (!missing.empty()) throw std::runtime_error("vulkan: " + ctx->info_.name + " lacks required features:" + missing);
        f2.features.samplerAnisotropy = s2.features.samplerAnisotropy;
        f2.features.depthClamp = s2.features.depthClamp;
    }

    std::vector<const char*> deviceExtensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (options.swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    if (rq.available) deviceExtensions.insert(deviceExtensions.end(), std::begin(rayExtensions), std::end(rayExtensions));

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = ctx->queueFamily_;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &f2;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    VK_CHECK(vkCreateDevice(ctx->physical_, &dci, nullptr, &ctx->device_));
    vkGetDeviceQueue(ctx->device_, ctx->queueFamily_, 0, &ctx->queue_);
    ctx->pushDescriptorSet_ = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(ctx->device_, "vkCmdPushDescriptorSetKHR"));

    if (rq.available) {
        auto load = [&](auto& fn, const char* name) {
            fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(vkGetDeviceProcAddr(ctx->device_, name));
            if (!fn) throw std::runtime_error(std::string("vulkan: ") + ctx->info_.name + " advertises ray queries but has no " + name);
        };
        load(rq.getBuildSizes, "vkGetAccelerationStructureBuildSizesKHR");
        load(rq.createAccelerationStructure, "vkCreateAccelerationStructureKHR");
        load(rq.destroyAccelerationStructure, "vkDestroyAccelerationStructureKHR");
        load(rq.cmdBuild, "vkCmdBuildAccelerationStructuresKHR");
        load(rq.getDeviceAddress, "vkGetAccelerationStructureDeviceAddressKHR");
        VkPhysicalDeviceAccelerationStructurePropertiesKHR accelProps{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
        VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        p2.pNext = &accelProps;
        vkGetPhysicalDeviceProperties2(ctx->physical_, &p2);
        rq.scratchAlignment = std::max<VkDeviceSize>(1, accelProps.minAccelerationStructureScratchOffsetAlignment);
    }

    VmaAllocatorCreateInfo aci{};
    if (rq.available) aci.flags |= VMA_ALLOCATOR_CREATE_BUFFER_DEVICE_ADDRESS_BIT;
    aci.vulkanApiVersion = VK_API_VERSION_1_3;
    aci.physicalDevice = ctx->physical_;
    aci.device = ctx->device_;
    aci.instance = ctx->instance_;
    // PPR_HEAP_LIMIT_MB=N: behave as a device whose heaps hold N MiB each (tests of the memory refusal;
    // lavapipe's heap is the host's RAM, larger than any request the CLI accepts).
    std::vector<VkDeviceSize> heapLimits;
    if (const char* limit = std::getenv("PPR_HEAP_LIMIT_MB"); limit && std::atoll(limit) > 0) {
        VkPhysicalDeviceMemoryProperties mp{};
        vkGetPhysicalDeviceMemoryProperties(ctx->physical_, &mp);
        heapLimits.assign(mp.memoryHeapCount, VkDeviceSize(std::atoll(limit)) * 1024 * 1024);
        aci.pHeapSizeLimit = heapLimits.data();
    }
    VK_CHECK(vmaCreateAllocator(&aci, &ctx->allocator_));

    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pci.queueFamilyIndex = ctx->queueFamily_;
    VK_CHECK(vkCreateCommandPool(ctx->device_, &pci, nullptr, &ctx->uploadPool_));

    ctx->name(ctx->device_, VK_OBJECT_TYPE_DEVICE, "ppr device");
    ctx->name(ctx->queue_, VK_OBJECT_TYPE_QUEUE, "ppr queue");
    ctx->name(ctx->uploadPool_, VK_OBJECT_TYPE_COMMAND_POOL, "upload command pool");
    return ctx;
}

Context::~Context() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        if (uploadPool_) vkDestroyCommandPool(device_, uploadPool_, nullptr);
        if (allocator_) vmaDestroyAllocator(allocator_);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::string Context::rayQueryUnavailableReason() const {
    if (rayQuery_.available) return {};
    return "this device lacks " + rayQuery_.missing + " (" + info_.name + (rayQuery_.hidden ? "; hidden by PPR_HIDE_RAY_QUERY=1" : "") + ")";
}

void Context::setName(VkObjectType type, uint64_t handle, const std::string& n) const {
    if (!setObjectName_ || !handle) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = n.c_str();
    setObjectName_(device_, &info);
}

void Context::beginLabel(VkCommandBuffer cmd, const char* label) const {
    if (!beginLabel_) return;
    VkDebugUtilsLabelEXT l{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT};
    l.pLabelName = label;
    beginLabel_(cmd, &l);
}

void Context::endLabel(VkCommandBuffer cmd) const {
    if (endLabel_) endLabel_(cmd);
}

void Context::immediateSubmit(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = uploadPool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    VK_CHECK(vkAllocateCommandBuffers(device_, &ai, &cmd));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK_CHECK(vkCreateFence(device_, &fci, nullptr, &fence));
    submit(*this, cmd, fence);
    VK_CHECK(vkWaitForFences(device_, 1, &fence, VK_TRUE, UINT64_MAX));
    vkDestroyFence(device_, fence, nullptr);
    vkFreeCommandBuffers(device_, uploadPool_, 1, &cmd);
}

void submit(const Context& ctx, VkCommandBuffer cmd, VkFence fence, VkSemaphore wait, VkPipelineStageFlags2 waitStage,
            VkSemaphore signal) {
    VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    waitInfo.semaphore = wait;
    waitInfo.stageMask = waitStage;
    VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signalInfo.semaphore = signal;
    signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cbi.commandBuffer = cmd;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.waitSemaphoreInfoCount = wait ? 1 : 0;
    si.pWaitSemaphoreInfos = &waitInfo;
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &cbi;
    si.signalSemaphoreInfoCount = signal ? 1 : 0;
    si.pSignalSemaphoreInfos = &signalInfo;
    VK_CHECK(vkQueueSubmit2(ctx.queue(), 1, &si, fence));
}

}  // namespace ppr::vk
