// Device selection and creation.
#include "common/vk/device.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "common/core/check.hpp"
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

struct Candidate {
    VkPhysicalDevice physical;
    VkPhysicalDeviceProperties properties;
    uint32_t queueFamily;
    std::string unsuitable;  // why it cannot be used; empty when it can
};

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return 0;
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return 1;
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return 2;
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return 3;
        default:
            return 4;
    }
}

bool hasDeviceExtension(VkPhysicalDevice physical, const char* name) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data()));
    for (const VkExtensionProperties& extension : extensions)
        if (std::strcmp(extension.extensionName, name) == 0) return true;
    return false;
}

std::string versionText(uint32_t version) {
    return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
           std::to_string(VK_API_VERSION_MINOR(version));
}

bool needsVulkan13Commands(const DeviceFeatures& wanted) {
    return wanted.dynamicRendering || wanted.synchronization2;
}

// What a chapter asks for, in words: "Vulkan 1.1", "Vulkan 1.3, or 1.2 with VK_KHR_...".
std::string requirement(const DeviceFeatures& wanted) {
    if (needsVulkan13Commands(wanted))
        return "Vulkan 1.3, or 1.2 with VK_KHR_dynamic_rendering and VK_KHR_synchronization2";
    return "Vulkan " + versionText(wanted.minApiVersion);
}

// The feature structures of one device, chained for vkGetPhysicalDeviceFeatures2 (to ask) or for
// vkCreateDevice (to enable): only those the device's version and the chapter's wishes call for.
// Vulkan 1.3 has dynamic rendering and synchronization2 in VkPhysicalDeviceVulkan13Features; a 1.2
// device has them in its extensions' own structures; scalar block layout is core 1.2.
struct FeatureChain {
    VkPhysicalDeviceMultiviewFeatures multiview{.sType =
                                                    VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MULTIVIEW_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceDynamicRenderingFeaturesKHR dynamicRendering{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
    VkPhysicalDeviceSynchronization2FeaturesKHR synchronization2{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES_KHR};
    void* head = nullptr;

    FeatureChain(uint32_t api, const DeviceFeatures& wanted) {
        auto link = [this](auto& structure) {
            structure.pNext = head;
            head = &structure;
        };
        if (api >= VK_API_VERSION_1_2 && (wanted.scalarBlockLayout || wanted.bufferDeviceAddress)) link(v12);
        if (wanted.multiview) link(multiview);
        if (api >= VK_API_VERSION_1_3 && needsVulkan13Commands(wanted)) link(v13);
        if (api < VK_API_VERSION_1_3 && wanted.dynamicRendering) link(dynamicRendering);
        if (api < VK_API_VERSION_1_3 && wanted.synchronization2) link(synchronization2);
    }
    FeatureChain(const FeatureChain&) = delete;  // the chain points into itself

    bool hasDynamicRendering(uint32_t api) const {
        return api >= VK_API_VERSION_1_3 ? v13.dynamicRendering : dynamicRendering.dynamicRendering;
    }
    bool hasSynchronization2(uint32_t api) const {
        return api >= VK_API_VERSION_1_3 ? v13.synchronization2 : synchronization2.synchronization2;
    }
};

// The device extensions the chapter's features take on this device (none on 1.3).
std::vector<const char*> featureExtensions(uint32_t api, const DeviceFeatures& wanted) {
    std::vector<const char*> extensions;
    if (api >= VK_API_VERSION_1_3) return extensions;
    if (wanted.dynamicRendering) extensions.push_back(VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME);
    if (wanted.synchronization2) extensions.push_back(VK_KHR_SYNCHRONIZATION_2_EXTENSION_NAME);
    return extensions;
}

// Why the device cannot give the chapter what it asks for, or an empty string when it can.
std::string missingFeatures(VkPhysicalDevice physical, uint32_t api, const DeviceFeatures& wanted) {
    uint32_t needed = needsVulkan13Commands(wanted) ? VK_API_VERSION_1_2 : wanted.minApiVersion;
    if (wanted.scalarBlockLayout || wanted.bufferDeviceAddress)
        needed = std::max(needed, uint32_t(VK_API_VERSION_1_2));
    if (api < needed)
        return "it supports Vulkan " + versionText(api) + "; this chapter needs " + requirement(wanted);
    std::string lacking;
    for (const char* extension : featureExtensions(api, wanted))
        if (!hasDeviceExtension(physical, extension))
            lacking += (lacking.empty() ? "" : " and ") + std::string(extension);
    if (!lacking.empty())
        return "it supports Vulkan " + versionText(api) + " without " + lacking + "; this chapter needs " +
               requirement(wanted);
    FeatureChain chain(api, wanted);
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                       .pNext = chain.head};
    vkGetPhysicalDeviceFeatures2(physical, &features);
    if (wanted.dynamicRendering && !chain.hasDynamicRendering(api))
        return "it lacks the dynamicRendering feature";
    if (wanted.synchronization2 && !chain.hasSynchronization2(api))
        return "it lacks the synchronization2 feature";
    if (wanted.scalarBlockLayout && !chain.v12.scalarBlockLayout)
        return "it lacks the scalarBlockLayout feature";
    if (wanted.bufferDeviceAddress && !chain.v12.bufferDeviceAddress)
        return "it lacks the bufferDeviceAddress feature";
    if (wanted.bufferDeviceAddress && !features.features.shaderInt64)
        return "it lacks the shaderInt64 feature";
    if (wanted.indirectDrawing && !features.features.multiDrawIndirect)
        return "it lacks the multiDrawIndirect feature";
    if (wanted.indirectDrawing && !features.features.drawIndirectFirstInstance)
        return "it lacks the drawIndirectFirstInstance feature";
    if (wanted.geometryShader && !features.features.geometryShader)
        return "it lacks the geometryShader feature";
    if (wanted.multiview && !chain.multiview.multiview) return "it lacks the multiview feature";
    if (wanted.vertexStores && !features.features.vertexPipelineStoresAndAtomics)
        return "it lacks the vertexPipelineStoresAndAtomics feature";
    if (wanted.preciseOcclusion && !features.features.occlusionQueryPrecise)
        return "it lacks the occlusionQueryPrecise feature";
    return {};
}

Candidate inspect(VkPhysicalDevice physical, VkSurfaceKHR surface, const DeviceFeatures& wanted) {
    Candidate candidate{physical, {}, 0, {}};
    vkGetPhysicalDeviceProperties(physical, &candidate.properties);
    candidate.unsuitable = missingFeatures(physical, candidate.properties.apiVersion, wanted);
    if (!candidate.unsuitable.empty()) return candidate;
    if (surface != VK_NULL_HANDLE && !hasDeviceExtension(physical, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) {
        candidate.unsuitable = "it has no VK_KHR_swapchain";
        return candidate;
    }
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &familyCount, families.data());
    for (uint32_t i = 0; i < familyCount; ++i) {
        if (!(families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) continue;
        VkBool32 canPresent = VK_TRUE;
        if (surface != VK_NULL_HANDLE)
            VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(physical, i, surface, &canPresent));
        if (canPresent) {
            candidate.queueFamily = i;
            return candidate;
        }
    }
    candidate.unsuitable = surface != VK_NULL_HANDLE
                               ? "no queue family can both draw and present to the window"
                               : "it has no graphics queue";
    return candidate;
}

std::string lowercase(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return result;
}

Candidate choose(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter,
                 const DeviceFeatures& wanted) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, nullptr));
    std::vector<VkPhysicalDevice> physicals(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance.handle, &count, physicals.data()));
    if (count == 0)
        throw Failure("no Vulkan device found (Debian/Ubuntu: apt-get install mesa-vulkan-drivers)");

    std::vector<Candidate> candidates;
    for (VkPhysicalDevice physical : physicals) candidates.push_back(inspect(physical, surface, wanted));

    std::string all;
    for (const Candidate& c : candidates)
        all += (all.empty() ? "'" : ", '") + std::string(c.properties.deviceName) + "'";

    std::vector<Candidate> matching;
    for (const Candidate& c : candidates)
        if (lowercase(c.properties.deviceName).find(lowercase(nameFilter)) != std::string::npos)
            matching.push_back(c);
    if (matching.empty())
        throw InputError("no Vulkan device matches --device '" + std::string(nameFilter) +
                         "' (devices: " + all + ")");

    std::stable_sort(matching.begin(), matching.end(), [](const Candidate& a, const Candidate& b) {
        if (a.unsuitable.empty() != b.unsuitable.empty()) return a.unsuitable.empty();
        return typeRank(a.properties.deviceType) < typeRank(b.properties.deviceType);
    });
    const Candidate& best = matching.front();
    if (!best.unsuitable.empty()) {
        // Where to get a device that can: Mesa's lavapipe has everything the chapters ask for; a
        // lavapipe too old for it (Debian 12's 22.3 has no ray tracing) has a newer one in Debian's
        // bookworm-backports, which scripts/mesa_backports.sh fetches without installing it.
        bool lavapipe = lowercase(best.properties.deviceName).find("llvmpipe") != std::string::npos;
        throw Failure(
            "cannot use Vulkan device '" + std::string(best.properties.deviceName) + "': " + best.unsuitable +
            (lavapipe ? " (a newer lavapipe may have it: scripts/mesa_backports.sh DIR fetches Mesa 25's; "
                        "run with VK_DRIVER_FILES=DIR/lvp_icd.json)"
                      : " (Mesa's lavapipe has what the chapters need: install mesa-vulkan-drivers and "
                        "run with --device llvmpipe)"));
    }
    return best;
}

}  // namespace

Vulkan13Commands vk13;

Device createDevice(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter,
                    const DeviceFeatures& features) {
    Candidate chosen = choose(instance, surface, nameFilter, features);
    Device device;
    device.physical = chosen.physical;
    device.properties = chosen.properties;
    device.apiVersion = chosen.properties.apiVersion;
    device.queueFamily = chosen.queueFamily;
    vkGetPhysicalDeviceMemoryProperties(device.physical, &device.memory);
    device.driver = "driver version " + std::to_string(device.properties.driverVersion);
    if (device.apiVersion >= VK_API_VERSION_1_2) {  // VkPhysicalDeviceDriverProperties is core 1.2
        VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                                .pNext = &driver};
        vkGetPhysicalDeviceProperties2(device.physical, &properties2);
        device.driver = std::string(driver.driverName) + ", " + driver.driverInfo;
    }
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &familyCount, families.data());
    device.timestampValidBits = families[device.queueFamily].timestampValidBits;

    std::vector<const char*> extensions = featureExtensions(device.apiVersion, features);
    device.features = "Vulkan " + versionText(device.apiVersion);
    for (const char* extension : extensions) device.features += std::string(" + ") + extension;
    if (surface != VK_NULL_HANDLE) {
        extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        // Lets the GUI pass view an _SRGB swapchain image as _UNORM (common/passes/gui_pass.cpp). It
        // builds on VK_KHR_image_format_list, core since 1.2.
        bool formatList = device.apiVersion >= VK_API_VERSION_1_2 ||
                          hasDeviceExtension(device.physical, VK_KHR_IMAGE_FORMAT_LIST_EXTENSION_NAME);
        if (formatList &&
            hasDeviceExtension(device.physical, VK_KHR_SWAPCHAIN_MUTABLE_FORMAT_EXTENSION_NAME)) {
            extensions.push_back(VK_KHR_SWAPCHAIN_MUTABLE_FORMAT_EXTENSION_NAME);
            if (device.apiVersion < VK_API_VERSION_1_2)
                extensions.push_back(VK_KHR_IMAGE_FORMAT_LIST_EXTENSION_NAME);
            device.swapchainMutableFormat = true;
        }
    }
    // Present fences, where the instance and the device have them (common/wnd/target.cpp).
    VkPhysicalDeviceSwapchainMaintenance1FeaturesEXT maintenance1{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SWAPCHAIN_MAINTENANCE_1_FEATURES_EXT};
    if (surface != VK_NULL_HANDLE && instance.surfaceMaintenance1 &&
        hasDeviceExtension(device.physical, VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME)) {
        VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2,
                                        .pNext = &maintenance1};
        vkGetPhysicalDeviceFeatures2(device.physical, &query);
        device.swapchainMaintenance1 = maintenance1.swapchainMaintenance1;
        if (device.swapchainMaintenance1) extensions.push_back(VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME);
    }
#if defined(VKBOOK_SHADER_DEBUG_INFO)
    // Shaders built with non-semantic debug information (glslang -gVS: VKBOOK_SHADER_DEBUG_INFO)
    // use this extension's instruction set; it is core from Vulkan 1.3 on.
    if (device.apiVersion < VK_API_VERSION_1_3 &&
        hasDeviceExtension(device.physical, VK_KHR_SHADER_NON_SEMANTIC_INFO_EXTENSION_NAME))
        extensions.push_back(VK_KHR_SHADER_NON_SEMANTIC_INFO_EXTENSION_NAME);
#endif
    // A portability implementation (MoltenVK) must have this extension enabled when it lists it.
    if (hasDeviceExtension(device.physical, "VK_KHR_portability_subset"))
        extensions.push_back("VK_KHR_portability_subset");

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{
        .sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
        .queueFamilyIndex = device.queueFamily,
        .queueCount = 1,
        .pQueuePriorities = &priority,
    };
    // Exactly the features asked for, no more: what a chapter uses is what it enables.
    FeatureChain enabled(device.apiVersion, features);
    enabled.v12.scalarBlockLayout = features.scalarBlockLayout;
    enabled.v12.bufferDeviceAddress = features.bufferDeviceAddress;
    enabled.multiview.multiview = features.multiview;
    enabled.v13.dynamicRendering = enabled.dynamicRendering.dynamicRendering = features.dynamicRendering;
    enabled.v13.synchronization2 = enabled.synchronization2.synchronization2 = features.synchronization2;
    maintenance1 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SWAPCHAIN_MAINTENANCE_1_FEATURES_EXT,
                    .pNext = enabled.head,
                    .swapchainMaintenance1 = VK_TRUE};
    // The core features of Vulkan 1.0 the chapter asks for (chapter-16: geometry shaders, and depth
    // clamping where the device has it).
    VkPhysicalDeviceFeatures available{};
    vkGetPhysicalDeviceFeatures(device.physical, &available);
    VkPhysicalDeviceFeatures coreFeatures{};
    coreFeatures.geometryShader = features.geometryShader ? VK_TRUE : VK_FALSE;
    coreFeatures.vertexPipelineStoresAndAtomics = features.vertexStores ? VK_TRUE : VK_FALSE;
    coreFeatures.occlusionQueryPrecise = features.preciseOcclusion ? VK_TRUE : VK_FALSE;
    coreFeatures.shaderInt64 = features.bufferDeviceAddress ? VK_TRUE : VK_FALSE;
    coreFeatures.multiDrawIndirect = features.indirectDrawing ? VK_TRUE : VK_FALSE;
    coreFeatures.drawIndirectFirstInstance = features.indirectDrawing ? VK_TRUE : VK_FALSE;
    device.depthClamp = features.depthClampWhereAvailable && available.depthClamp;
    coreFeatures.depthClamp = device.depthClamp ? VK_TRUE : VK_FALSE;
    VkDeviceCreateInfo createInfo{
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = device.swapchainMaintenance1 ? static_cast<void*>(&maintenance1) : enabled.head,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &queueInfo,
        .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
        .ppEnabledExtensionNames = extensions.data(),
        .pEnabledFeatures = &coreFeatures,
    };
    VK_CHECK(vkCreateDevice(device.physical, &createInfo, nullptr, &device.handle));
    vkGetDeviceQueue(device.handle, device.queueFamily, 0, &device.queue);

    // The same commands under their core names (1.3) or their extensions' (1.2).
    if (needsVulkan13Commands(features)) {
        bool core = device.apiVersion >= VK_API_VERSION_1_3;
        auto load = [&](const char* coreName, const char* extensionName) {
            PFN_vkVoidFunction function = vkGetDeviceProcAddr(device.handle, core ? coreName : extensionName);
            if (!function)
                throw Failure(std::string("the driver has no ") + (core ? coreName : extensionName));
            return function;
        };
        vk13.CmdBeginRendering =
            reinterpret_cast<PFN_vkCmdBeginRendering>(load("vkCmdBeginRendering", "vkCmdBeginRenderingKHR"));
        vk13.CmdEndRendering =
            reinterpret_cast<PFN_vkCmdEndRendering>(load("vkCmdEndRendering", "vkCmdEndRenderingKHR"));
        vk13.CmdPipelineBarrier2 = reinterpret_cast<PFN_vkCmdPipelineBarrier2>(
            load("vkCmdPipelineBarrier2", "vkCmdPipelineBarrier2KHR"));
        vk13.QueueSubmit2 = reinterpret_cast<PFN_vkQueueSubmit2>(load("vkQueueSubmit2", "vkQueueSubmit2KHR"));
    }

    VkCommandPoolCreateInfo poolInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
        .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
        .queueFamilyIndex = device.queueFamily,
    };
    VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &device.oneTimePool));
    nameObject(device.handle, device.oneTimePool, "one-time commands");
    nameObject(device.handle, device.queue, "graphics queue");
    return device;
}

void destroyDevice(Device& device) {
    for (const Device::RetiredPipeline& retired : device.retiredPipelines)  // replaced in the last frames
        vkDestroyPipeline(device.handle, retired.pipeline, nullptr);
    vkDestroyCommandPool(device.handle, device.oneTimePool, nullptr);
    vkDestroyDevice(device.handle, nullptr);
    device = {};
    vk13 = {};
}

}  // namespace common
