// Instance creation, the validation layer and the debug messenger.
#include "common/vk/instance.hpp"

#include <atomic>
#include <cstdio>
#include <cstring>
#include <string>

#if defined(_WIN32)
#include <windows.h>
#endif

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

// True when this Windows program runs under Wine. Wine's Vulkan loader lists no layers (Debian
// has no Windows build of the validation layer), but the Linux loader that winevulkan calls into
// can load the Linux validation layer itself (VK_LOADER_LAYERS_ENABLE=*validation in the
// environment Wine was started from), and its messages reach our messenger all the same. That is
// how the Windows build is tested with --validation (tests/desktops/windows.cmake).
bool runningUnderWine() {
#if defined(_WIN32)
    HMODULE ntdll = GetModuleHandleW(L"ntdll.dll");
    return ntdll && GetProcAddress(ntdll, "wine_get_version") != nullptr;
#else
    return false;
#endif
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
std::atomic<uint32_t> gValidationMessages{0};

VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
    ++gValidationMessages;
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::fprintf(stderr, "validation %s: %s\n", level, data->pMessage);
    return VK_FALSE;  // never abort the call that triggered the message
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo() {
    return {
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = debugCallback,
    };
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const VkLayerProperties& layer : layers)
        if (std::strcmp(layer.layerName, name) == 0) return true;
    return false;
}

}  // namespace

bool hasInstanceExtension(const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data()));
    for (const VkExtensionProperties& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

uint32_t validationMessageCount() {
    return gValidationMessages.load();
}

Instance createInstance(const char* applicationName, bool validation, std::vector<const char*> extensions) {
    uint32_t apiVersion = 0;
    VK_CHECK(vkEnumerateInstanceVersion(&apiVersion));
    // The loader, not the device: any 1.1 loader takes an application of a later version and
    // hands each device its own (common/vk/device.cpp asks each device for what its chapter needs).
    if (apiVersion < VK_API_VERSION_1_1)
        throw Failure("the Vulkan loader supports API " + std::to_string(VK_API_VERSION_MAJOR(apiVersion)) +
                      "." + std::to_string(VK_API_VERSION_MINOR(apiVersion)) + "; these chapters need 1.1");

    VkApplicationInfo appInfo{
        .sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
        .pApplicationName = applicationName,
        .applicationVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .pEngineName = "vulkan-book-cpp",
        .engineVersion = VK_MAKE_API_VERSION(0, 1, 0, 0),
        .apiVersion = VK_API_VERSION_1_3,
    };

    // Portability drivers (MoltenVK) are only listed when the application says it can use them.
    VkInstanceCreateFlags flags = 0;
    if (hasInstanceExtension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
        flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }

    std::vector<const char*> layers;
    // Synchronization validation is off by default in the layer; it is what catches a missing
    // barrier between the passes of a deferred renderer, so every --validation run enables it.
    VkValidationFeatureEnableEXT enabledFeatures[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT validationFeatures{
        .sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT,
        .enabledValidationFeatureCount = 1,
        .pEnabledValidationFeatures = enabledFeatures,
    };
    // Chained into VkInstanceCreateInfo, the messenger also reports on vkCreateInstance and
    // vkDestroyInstance themselves.
    VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo();
    debugInfo.pNext = &validationFeatures;
    if (validation) {
        if (hasLayer(kValidationLayer)) {
            layers.push_back(kValidationLayer);
        } else if (!runningUnderWine()) {
            throw Failure(
                std::string(kValidationLayer) +
                " is not installed (Debian/Ubuntu: apt-get install vulkan-validationlayers; Windows "
                "and macOS: the Vulkan SDK)");
        }
    }
    // VK_EXT_debug_utils: the messenger above, and the names and labels a debugger shows
    // (common/vk/debug_names.hpp), wherever the instance offers it; the validation layer always does.
    bool debugUtils = validation || hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

    VkInstanceCreateInfo createInfo{
        .sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
        .pNext = validation ? &debugInfo : nullptr,
        .flags = flags,
        .pApplicationInfo = &appInfo,
        .enabledLayerCount = static_cast<uint32_t>(layers.size()),
        .ppEnabledLayerNames = layers.data(),
        .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
        .ppEnabledExtensionNames = extensions.data(),
    };
    Instance instance;
    VK_CHECK(vkCreateInstance(&createInfo, nullptr, &instance.handle));
    for (const char* extension : extensions)
        if (std::strcmp(extension, VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME) == 0)
            instance.surfaceMaintenance1 = true;

    loadDebugNames(instance.handle, debugUtils);
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance.handle, "vkCreateDebugUtilsMessengerEXT"));
        VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo();
        VK_CHECK(create(instance.handle, &info, nullptr, &instance.messenger));
    }
    return instance;
}

void destroyInstance(Instance& instance) {
    if (instance.messenger != VK_NULL_HANDLE) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance.handle, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance.handle, instance.messenger, nullptr);
    }
    vkDestroyInstance(instance.handle, nullptr);
    instance = {};
}

}  // namespace common
