// What the two test layers share (fault_layer/fault_layer.cpp, whose comments explain the layer
// interface, and names_layer/names_layer.cpp): the dispatch key of a handle, the loader's link in
// a create call's pNext chain, and the three entry points the loader looks up by name.
#pragma once

#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

namespace layer {

// Dispatchable handles of one instance (or device) share the first word: the loader's dispatch
// table, the key of a layer's per-instance (per-device) data.
inline void* dispatchKey(const void* handle) {
    return *static_cast<void* const*>(handle);
}

// The loader's VK_LAYER_LINK_INFO in a vkCreateInstance or vkCreateDevice pNext chain: where the
// next layer's GetProcAddr is. The caller advances it (pLayerInfo = pLayerInfo->pNext) for the
// next layer before calling down.
template <typename CreateInfo>
CreateInfo* findLinkInfo(const void* pNext, VkStructureType type) {
    auto* info = static_cast<CreateInfo*>(const_cast<void*>(pNext));
    while (info != nullptr && !(info->sType == type && info->function == VK_LAYER_LINK_INFO))
        info = static_cast<CreateInfo*>(const_cast<void*>(info->pNext));
    return info;
}

}  // namespace layer

// The three entry points the loader looks up by name, each handing over to the layer's own
// functions. Inside a layer only those are called: an exported vkGetInstanceProcAddr could bind
// to the loader's own.
#define VKBOOK_LAYER_ENTRY_POINTS(getInstanceProcAddr, getDeviceProcAddr)                               \
    extern "C" {                                                                                        \
    VK_LAYER_EXPORT VKAPI_ATTR VkResult VKAPI_CALL                                                      \
    vkNegotiateLoaderLayerInterfaceVersion(VkNegotiateLayerInterface* version) {                        \
        if (version->loaderLayerInterfaceVersion < 2) return VK_ERROR_INITIALIZATION_FAILED;            \
        version->loaderLayerInterfaceVersion = 2;                                                       \
        version->pfnGetInstanceProcAddr = getInstanceProcAddr;                                          \
        version->pfnGetDeviceProcAddr = getDeviceProcAddr;                                              \
        version->pfnGetPhysicalDeviceProcAddr = nullptr;                                                \
        return VK_SUCCESS;                                                                              \
    }                                                                                                   \
    VK_LAYER_EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetInstanceProcAddr(VkInstance instance, \
                                                                                   const char* name) {  \
        return getInstanceProcAddr(instance, name);                                                     \
    }                                                                                                   \
    VK_LAYER_EXPORT VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL vkGetDeviceProcAddr(VkDevice device,       \
                                                                                 const char* name) {    \
        return getDeviceProcAddr(device, name);                                                         \
    }                                                                                                   \
    }
