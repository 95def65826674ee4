// VK_LAYER_VKBOOK_object_names: a Vulkan layer that records what a graphics debugger would show
// of a run -- which objects were given names (vkSetDebugUtilsObjectNameEXT) and which command
// buffer regions were labelled (vkCmdBeginDebugUtilsLabelEXT) -- so a test can check that every
// object a chapter creates has a name and every pass a label (tests/reliability/names.cmake).
//
// Recorded: every object the device creates or allocates (images, buffers and their memory, image
// views, samplers, pipelines and their layouts and cache, shader modules, render passes,
// framebuffers, descriptor set layouts, pools and sets, command pools and buffers, semaphores,
// fences, query pools, swapchains), and the names set on them; every label begun and ended. At
// vkDestroyDevice the layer appends a report to the file VKBOOK_NAMES_REPORT names:
//   named <type> <name>          an object, and the last name given to it
//   unnamed <type> <handle>      an object created and never named (or named "")
//   label <name>                 a label begun, once per name
//   unbalanced <n>               labels begun minus labels ended (0 is not printed)
// Every call passes down unchanged. Like the fault-injection layer (fault_layer/fault_layer.cpp,
// whose comments explain the layer interface), it is an implicit layer enabled only when
// VKBOOK_NAMES_LAYER=1.
#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "../layer_common.hpp"

namespace {

using layer::dispatchKey;
using layer::findLinkInfo;

struct InstanceData {
    VkInstance handle = VK_NULL_HANDLE;
    PFN_vkGetInstanceProcAddr next = nullptr;
};

// An object as created: its type, and the name it was given last ("" until then).
struct Object {
    const char* type;
    uint64_t handle;
    std::string name;
};

struct DeviceData {
    PFN_vkGetDeviceProcAddr getProcAddr = nullptr;
    std::vector<Object> objects;                                 // in creation order
    std::map<std::pair<VkObjectType, uint64_t>, size_t> latest;  // (type, handle) -> its newest object
    std::set<std::string> labels;
    long long openLabels = 0;
    struct {
        PFN_vkDestroyDevice destroyDevice;
        PFN_vkCreateImage createImage;
        PFN_vkCreateBuffer createBuffer;
        PFN_vkCreateGraphicsPipelines createGraphicsPipelines;
        PFN_vkCreateComputePipelines createComputePipelines;
        PFN_vkCreateShaderModule createShaderModule;
        PFN_vkCreateDescriptorSetLayout createDescriptorSetLayout;
        PFN_vkCreateCommandPool createCommandPool;
        PFN_vkAllocateMemory allocateMemory;
        PFN_vkCreateImageView createImageView;
        PFN_vkCreateSampler createSampler;
        PFN_vkCreatePipelineLayout createPipelineLayout;
        PFN_vkCreatePipelineCache createPipelineCache;
        PFN_vkCreateRenderPass createRenderPass;
        PFN_vkCreateFramebuffer createFramebuffer;
        PFN_vkCreateDescriptorPool createDescriptorPool;
        PFN_vkCreateSemaphore createSemaphore;
        PFN_vkCreateFence createFence;
        PFN_vkCreateQueryPool createQueryPool;
        PFN_vkCreateSwapchainKHR createSwapchain;
        PFN_vkAllocateDescriptorSets allocateDescriptorSets;
        PFN_vkAllocateCommandBuffers allocateCommandBuffers;
        PFN_vkSetDebugUtilsObjectNameEXT setObjectName;
        PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel;
        PFN_vkCmdEndDebugUtilsLabelEXT endLabel;
    } next{};
};

std::mutex gLock;
std::unordered_map<void*, InstanceData> gInstances;
std::unordered_map<void*, DeviceData> gDevices;

InstanceData& instanceData(const void* handle) {
    std::lock_guard lock(gLock);
    return gInstances.at(dispatchKey(handle));
}

DeviceData& deviceData(const void* handle) {
    std::lock_guard lock(gLock);
    return gDevices.at(dispatchKey(handle));
}

template <typename Handle>
void record(DeviceData& device, VkObjectType type, const char* typeName, const Handle* handles,
            uint32_t count) {
    std::lock_guard lock(gLock);
    for (uint32_t i = 0; i < count; ++i) {
        uint64_t handle = reinterpret_cast<uint64_t>(handles[i]);
        if (handle == 0) continue;
        device.latest[{type, handle}] = device.objects.size();
        device.objects.push_back({typeName, handle, ""});
    }
}

VKAPI_ATTR VkResult VKAPI_CALL createInstance(const VkInstanceCreateInfo* createInfo,
                                              const VkAllocationCallbacks* allocator, VkInstance* instance) {
    auto* link = findLinkInfo<VkLayerInstanceCreateInfo>(createInfo->pNext,
                                                         VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO);
    if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(next(VK_NULL_HANDLE, "vkCreateInstance"));
    VkResult result = create(createInfo, allocator, instance);
    if (result != VK_SUCCESS) return result;
    std::lock_guard lock(gLock);
    gInstances[dispatchKey(*instance)] = {*instance, next};
    return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL destroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator) {
    if (instance == VK_NULL_HANDLE) return;
    InstanceData data = instanceData(instance);
    {
        std::lock_guard lock(gLock);
        gInstances.erase(dispatchKey(instance));
    }
    reinterpret_cast<PFN_vkDestroyInstance>(data.next(instance, "vkDestroyInstance"))(instance, allocator);
}

template <typename Function>
void resolve(Function& function, PFN_vkGetDeviceProcAddr next, VkDevice device, const char* name) {
    function = reinterpret_cast<Function>(next(device, name));
}

VKAPI_ATTR VkResult VKAPI_CALL createDevice(VkPhysicalDevice physical, const VkDeviceCreateInfo* createInfo,
                                            const VkAllocationCallbacks* allocator, VkDevice* device) {
    auto* link =
        findLinkInfo<VkLayerDeviceCreateInfo>(createInfo->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO);
    if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr nextInstance = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    PFN_vkGetDeviceProcAddr next = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    VkInstance instance = instanceData(physical).handle;
    auto create = reinterpret_cast<PFN_vkCreateDevice>(nextInstance(instance, "vkCreateDevice"));
    VkResult result = create(physical, createInfo, allocator, device);
    if (result != VK_SUCCESS) return result;
    DeviceData data;
    data.getProcAddr = next;
    resolve(data.next.destroyDevice, next, *device, "vkDestroyDevice");
    resolve(data.next.createImage, next, *device, "vkCreateImage");
    resolve(data.next.createBuffer, next, *device, "vkCreateBuffer");
    resolve(data.next.createGraphicsPipelines, next, *device, "vkCreateGraphicsPipelines");
    resolve(data.next.createComputePipelines, next, *device, "vkCreateComputePipelines");
    resolve(data.next.createShaderModule, next, *device, "vkCreateShaderModule");
    resolve(data.next.createDescriptorSetLayout, next, *device, "vkCreateDescriptorSetLayout");
    resolve(data.next.createCommandPool, next, *device, "vkCreateCommandPool");
    resolve(data.next.allocateMemory, next, *device, "vkAllocateMemory");
    resolve(data.next.createImageView, next, *device, "vkCreateImageView");
    resolve(data.next.createSampler, next, *device, "vkCreateSampler");
    resolve(data.next.createPipelineLayout, next, *device, "vkCreatePipelineLayout");
    resolve(data.next.createPipelineCache, next, *device, "vkCreatePipelineCache");
    resolve(data.next.createRenderPass, next, *device, "vkCreateRenderPass");
    resolve(data.next.createFramebuffer, next, *device, "vkCreateFramebuffer");
    resolve(data.next.createDescriptorPool, next, *device, "vkCreateDescriptorPool");
    resolve(data.next.createSemaphore, next, *device, "vkCreateSemaphore");
    resolve(data.next.createFence, next, *device, "vkCreateFence");
    resolve(data.next.createQueryPool, next, *device, "vkCreateQueryPool");
    resolve(data.next.createSwapchain, next, *device, "vkCreateSwapchainKHR");
    resolve(data.next.allocateDescriptorSets, next, *device, "vkAllocateDescriptorSets");
    resolve(data.next.allocateCommandBuffers, next, *device, "vkAllocateCommandBuffers");
    resolve(data.next.setObjectName, next, *device, "vkSetDebugUtilsObjectNameEXT");
    resolve(data.next.beginLabel, next, *device, "vkCmdBeginDebugUtilsLabelEXT");
    resolve(data.next.endLabel, next, *device, "vkCmdEndDebugUtilsLabelEXT");
    std::lock_guard lock(gLock);
    gDevices[dispatchKey(*device)] = data;
    return VK_SUCCESS;
}

void writeReport(const DeviceData& device) {
    const char* path = std::getenv("VKBOOK_NAMES_REPORT");
    if (path == nullptr || *path == '\0') return;
    std::FILE* file = std::fopen(path, "a");
    if (file == nullptr) {
        std::fprintf(stderr, "VK_LAYER_VKBOOK_object_names: cannot write '%s'\n", path);
        return;
    }
    for (const Object& object : device.objects) {
        if (object.name.empty())
            std::fprintf(file, "unnamed %s 0x%llx\n", object.type,
                         static_cast<unsigned long long>(object.handle));
        else
            std::fprintf(file, "named %s %s\n", object.type, object.name.c_str());
    }
    for (const std::string& label : device.labels) std::fprintf(file, "label %s\n", label.c_str());
    if (device.openLabels != 0) std::fprintf(file, "unbalanced %lld\n", device.openLabels);
    std::fclose(file);
}

VKAPI_ATTR void VKAPI_CALL destroyDevice(VkDevice device, const VkAllocationCallbacks* allocator) {
    if (device == VK_NULL_HANDLE) return;
    DeviceData data;
    {
        std::lock_guard lock(gLock);
        data = std::move(gDevices.at(dispatchKey(device)));
        gDevices.erase(dispatchKey(device));
    }
    writeReport(data);
    data.next.destroyDevice(device, allocator);
}

// ---- What is recorded ---------------------------------------------------------------------------

VKAPI_ATTR VkResult VKAPI_CALL createImage(VkDevice device, const VkImageCreateInfo* info,
                                           const VkAllocationCallbacks* allocator, VkImage* image) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createImage(device, info, allocator, image);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_IMAGE, "image", image, 1);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createBuffer(VkDevice device, const VkBufferCreateInfo* info,
                                            const VkAllocationCallbacks* allocator, VkBuffer* buffer) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createBuffer(device, info, allocator, buffer);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_BUFFER, "buffer", buffer, 1);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createGraphicsPipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                       const VkGraphicsPipelineCreateInfo* infos,
                                                       const VkAllocationCallbacks* allocator,
                                                       VkPipeline* pipelines) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createGraphicsPipelines(device, cache, count, infos, allocator, pipelines);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_PIPELINE, "pipeline", pipelines, count);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createComputePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                      const VkComputePipelineCreateInfo* infos,
                                                      const VkAllocationCallbacks* allocator,
                                                      VkPipeline* pipelines) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createComputePipelines(device, cache, count, infos, allocator, pipelines);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_PIPELINE, "pipeline", pipelines, count);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createShaderModule(VkDevice device, const VkShaderModuleCreateInfo* info,
                                                  const VkAllocationCallbacks* allocator,
                                                  VkShaderModule* module) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createShaderModule(device, info, allocator, module);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_SHADER_MODULE, "shader-module", module, 1);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createDescriptorSetLayout(VkDevice device,
                                                         const VkDescriptorSetLayoutCreateInfo* info,
                                                         const VkAllocationCallbacks* allocator,
                                                         VkDescriptorSetLayout* layout) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createDescriptorSetLayout(device, info, allocator, layout);
    if (result == VK_SUCCESS)
        record(data, VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, "descriptor-set-layout", layout, 1);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL createCommandPool(VkDevice device, const VkCommandPoolCreateInfo* info,
                                                 const VkAllocationCallbacks* allocator,
                                                 VkCommandPool* pool) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createCommandPool(device, info, allocator, pool);
    if (result == VK_SUCCESS) record(data, VK_OBJECT_TYPE_COMMAND_POOL, "command-pool", pool, 1);
    return result;
}

// The other objects a device makes, each recorded the same way.
#define RECORD_CREATE(function, member, Info, Handle, type, typeName)                                 \
    VKAPI_ATTR VkResult VKAPI_CALL function(VkDevice device, const Info* info,                        \
                                            const VkAllocationCallbacks* allocator, Handle* handle) { \
        DeviceData& data = deviceData(device);                                                        \
        VkResult result = data.next.member(device, info, allocator, handle);                          \
        if (result == VK_SUCCESS) record(data, type, typeName, handle, 1);                            \
        return result;                                                                                \
    }
RECORD_CREATE(allocateMemory, allocateMemory, VkMemoryAllocateInfo, VkDeviceMemory,
              VK_OBJECT_TYPE_DEVICE_MEMORY, "memory")
RECORD_CREATE(createImageView, createImageView, VkImageViewCreateInfo, VkImageView, VK_OBJECT_TYPE_IMAGE_VIEW,
              "image-view")
RECORD_CREATE(createSampler, createSampler, VkSamplerCreateInfo, VkSampler, VK_OBJECT_TYPE_SAMPLER, "sampler")
RECORD_CREATE(createPipelineLayout, createPipelineLayout, VkPipelineLayoutCreateInfo, VkPipelineLayout,
              VK_OBJECT_TYPE_PIPELINE_LAYOUT, "pipeline-layout")
RECORD_CREATE(createPipelineCache, createPipelineCache, VkPipelineCacheCreateInfo, VkPipelineCache,
              VK_OBJECT_TYPE_PIPELINE_CACHE, "pipeline-cache")
RECORD_CREATE(createRenderPass, createRenderPass, VkRenderPassCreateInfo, VkRenderPass,
              VK_OBJECT_TYPE_RENDER_PASS, "render-pass")
RECORD_CREATE(createFramebuffer, createFramebuffer, VkFramebufferCreateInfo, VkFramebuffer,
              VK_OBJECT_TYPE_FRAMEBUFFER, "framebuffer")
RECORD_CREATE(createDescriptorPool, createDescriptorPool, VkDescriptorPoolCreateInfo, VkDescriptorPool,
              VK_OBJECT_TYPE_DESCRIPTOR_POOL, "descriptor-pool")
RECORD_CREATE(createSemaphore, createSemaphore, VkSemaphoreCreateInfo, VkSemaphore, VK_OBJECT_TYPE_SEMAPHORE,
              "semaphore")
RECORD_CREATE(createFence, createFence, VkFenceCreateInfo, VkFence, VK_OBJECT_TYPE_FENCE, "fence")
RECORD_CREATE(createQueryPool, createQueryPool, VkQueryPoolCreateInfo, VkQueryPool, VK_OBJECT_TYPE_QUERY_POOL,
              "query-pool")
RECORD_CREATE(createSwapchain, createSwapchain, VkSwapchainCreateInfoKHR, VkSwapchainKHR,
              VK_OBJECT_TYPE_SWAPCHAIN_KHR, "swapchain")
#undef RECORD_CREATE

VKAPI_ATTR VkResult VKAPI_CALL allocateDescriptorSets(VkDevice device,
                                                      const VkDescriptorSetAllocateInfo* info,
                                                      VkDescriptorSet* sets) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.allocateDescriptorSets(device, info, sets);
    if (result == VK_SUCCESS)
        record(data, VK_OBJECT_TYPE_DESCRIPTOR_SET, "descriptor-set", sets, info->descriptorSetCount);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL allocateCommandBuffers(VkDevice device,
                                                      const VkCommandBufferAllocateInfo* info,
                                                      VkCommandBuffer* buffers) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.allocateCommandBuffers(device, info, buffers);
    if (result == VK_SUCCESS)
        record(data, VK_OBJECT_TYPE_COMMAND_BUFFER, "command-buffer", buffers, info->commandBufferCount);
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL setObjectName(VkDevice device, const VkDebugUtilsObjectNameInfoEXT* info) {
    DeviceData& data = deviceData(device);
    {
        std::lock_guard lock(gLock);
        auto found = data.latest.find({info->objectType, info->objectHandle});
        if (found != data.latest.end())
            data.objects[found->second].name = info->pObjectName ? info->pObjectName : "";
    }
    return data.next.setObjectName ? data.next.setObjectName(device, info) : VK_SUCCESS;
}

// Command buffers are dispatchable and share their device's dispatch key.
VKAPI_ATTR void VKAPI_CALL beginLabel(VkCommandBuffer cmd, const VkDebugUtilsLabelEXT* label) {
    DeviceData& data = deviceData(cmd);
    {
        std::lock_guard lock(gLock);
        data.labels.insert(label->pLabelName ? label->pLabelName : "");
        ++data.openLabels;
    }
    if (data.next.beginLabel) data.next.beginLabel(cmd, label);
}

VKAPI_ATTR void VKAPI_CALL endLabel(VkCommandBuffer cmd) {
    DeviceData& data = deviceData(cmd);
    {
        std::lock_guard lock(gLock);
        --data.openLabels;
    }
    if (data.next.endLabel) data.next.endLabel(cmd);
}

// ---- GetProcAddr ----------------------------------------------------------------------------------

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name);

PFN_vkVoidFunction interceptedDeviceCall(const char* name) {
    static const std::unordered_map<std::string, PFN_vkVoidFunction> calls = {
        {"vkGetDeviceProcAddr", reinterpret_cast<PFN_vkVoidFunction>(getDeviceProcAddr)},
        {"vkDestroyDevice", reinterpret_cast<PFN_vkVoidFunction>(destroyDevice)},
        {"vkCreateImage", reinterpret_cast<PFN_vkVoidFunction>(createImage)},
        {"vkCreateBuffer", reinterpret_cast<PFN_vkVoidFunction>(createBuffer)},
        {"vkCreateGraphicsPipelines", reinterpret_cast<PFN_vkVoidFunction>(createGraphicsPipelines)},
        {"vkCreateComputePipelines", reinterpret_cast<PFN_vkVoidFunction>(createComputePipelines)},
        {"vkCreateShaderModule", reinterpret_cast<PFN_vkVoidFunction>(createShaderModule)},
        {"vkCreateDescriptorSetLayout", reinterpret_cast<PFN_vkVoidFunction>(createDescriptorSetLayout)},
        {"vkCreateCommandPool", reinterpret_cast<PFN_vkVoidFunction>(createCommandPool)},
        {"vkAllocateMemory", reinterpret_cast<PFN_vkVoidFunction>(allocateMemory)},
        {"vkCreateImageView", reinterpret_cast<PFN_vkVoidFunction>(createImageView)},
        {"vkCreateSampler", reinterpret_cast<PFN_vkVoidFunction>(createSampler)},
        {"vkCreatePipelineLayout", reinterpret_cast<PFN_vkVoidFunction>(createPipelineLayout)},
        {"vkCreatePipelineCache", reinterpret_cast<PFN_vkVoidFunction>(createPipelineCache)},
        {"vkCreateRenderPass", reinterpret_cast<PFN_vkVoidFunction>(createRenderPass)},
        {"vkCreateFramebuffer", reinterpret_cast<PFN_vkVoidFunction>(createFramebuffer)},
        {"vkCreateDescriptorPool", reinterpret_cast<PFN_vkVoidFunction>(createDescriptorPool)},
        {"vkCreateSemaphore", reinterpret_cast<PFN_vkVoidFunction>(createSemaphore)},
        {"vkCreateFence", reinterpret_cast<PFN_vkVoidFunction>(createFence)},
        {"vkCreateQueryPool", reinterpret_cast<PFN_vkVoidFunction>(createQueryPool)},
        {"vkCreateSwapchainKHR", reinterpret_cast<PFN_vkVoidFunction>(createSwapchain)},
        {"vkAllocateDescriptorSets", reinterpret_cast<PFN_vkVoidFunction>(allocateDescriptorSets)},
        {"vkAllocateCommandBuffers", reinterpret_cast<PFN_vkVoidFunction>(allocateCommandBuffers)},
        {"vkSetDebugUtilsObjectNameEXT", reinterpret_cast<PFN_vkVoidFunction>(setObjectName)},
        {"vkCmdBeginDebugUtilsLabelEXT", reinterpret_cast<PFN_vkVoidFunction>(beginLabel)},
        {"vkCmdEndDebugUtilsLabelEXT", reinterpret_cast<PFN_vkVoidFunction>(endLabel)},
    };
    auto found = calls.find(name);
    return found == calls.end() ? nullptr : found->second;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name) {
    PFN_vkGetDeviceProcAddr next = deviceData(device).getProcAddr;
    if (PFN_vkVoidFunction ours = interceptedDeviceCall(name); ours && next(device, name)) return ours;
    return next(device, name);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getInstanceProcAddr(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkGetInstanceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(getInstanceProcAddr);
    if (std::strcmp(name, "vkCreateInstance") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(createInstance);
    if (std::strcmp(name, "vkDestroyInstance") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(destroyInstance);
    if (std::strcmp(name, "vkCreateDevice") == 0) return reinterpret_cast<PFN_vkVoidFunction>(createDevice);
    if (PFN_vkVoidFunction ours = interceptedDeviceCall(name)) return ours;
    if (instance == VK_NULL_HANDLE) return nullptr;
    return instanceData(instance).next(instance, name);
}

}  // namespace

VKBOOK_LAYER_ENTRY_POINTS(getInstanceProcAddr, getDeviceProcAddr)
