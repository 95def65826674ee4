// Device selection and creation.
#include "common/device.hpp"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "common/check.hpp"

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

// The first feature in `wanted` the device lacks, or nullptr.
const char* missingFeature(VkPhysicalDevice physical, const DeviceFeatures& wanted) {
    VkPhysicalDeviceVulkan13Features v13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         .pNext = &v13};
    VkPhysicalDeviceFeatures2 features{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &v12};
    vkGetPhysicalDeviceFeatures2(physical, &features);
    if (wanted.dynamicRendering && !v13.dynamicRendering) return "dynamicRendering";
    if (wanted.synchronization2 && !v13.synchronization2) return "synchronization2";
    if (wanted.scalarBlockLayout && !v12.scalarBlockLayout) return "scalarBlockLayout";
    if (wanted.maintenance4 && !v13.maintenance4) return "maintenance4";
    return nullptr;
}

Candidate inspect(VkPhysicalDevice physical, VkSurfaceKHR surface, const DeviceFeatures& wanted) {
    Candidate candidate{physical, {}, 0, {}};
    vkGetPhysicalDeviceProperties(physical, &candidate.properties);
    if (candidate.properties.apiVersion < VK_API_VERSION_1_3) {
        candidate.unsuitable = "it supports Vulkan 1." +
                               std::to_string(VK_API_VERSION_MINOR(candidate.properties.apiVersion)) +
                               ", not 1.3";
        return candidate;
    }
    if (const char* missing = missingFeature(physical, wanted)) {
        candidate.unsuitable = std::string("it lacks the ") + missing + " feature";
        return candidate;
    }
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
    if (!best.unsuitable.empty())
        throw Failure("cannot use Vulkan device '" + std::string(best.properties.deviceName) +
                      "': " + best.unsuitable);
    return best;
}

}  // namespace

Device createDevice(const Instance& instance, VkSurfaceKHR surface, std::string_view nameFilter,
                    const DeviceFeatures& features) {
    Candidate chosen = choose(instance, surface, nameFilter, features);
    Device device;
    device.physical = chosen.physical;
    device.properties = chosen.properties;
    device.queueFamily = chosen.queueFamily;
    vkGetPhysicalDeviceMemoryProperties(device.physical, &device.memory);
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                            .pNext = &driver};
    vkGetPhysicalDeviceProperties2(device.physical, &properties2);
    device.driver = std::string(driver.driverName) + ", " + driver.driverInfo;
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(device.physical, &familyCount, families.data());
    device.timestampValidBits = families[device.queueFamily].timestampValidBits;

    std::vector<const char*> extensions;
    if (surface != VK_NULL_HANDLE) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
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
    VkPhysicalDeviceVulkan13Features v13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                         .synchronization2 = features.synchronization2,
                                         .dynamicRendering = features.dynamicRendering,
                                         .maintenance4 = features.maintenance4};
    VkPhysicalDeviceVulkan12Features v12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         .pNext = &v13,
                                         .scalarBlockLayout = features.scalarBlockLayout};
    VkDeviceCreateInfo createInfo{
        .sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
        .pNext = &v12,
        .queueCreateInfoCount = 1,
        .pQueueCreateInfos = &queueInfo,
        .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
        .ppEnabledExtensionNames = extensions.data(),
    };
    VK_CHECK(vkCreateDevice(device.physical, &createInfo, nullptr, &device.handle));
    vkGetDeviceQueue(device.handle, device.queueFamily, 0, &device.queue);

    VkCommandPoolCreateInfo poolInfo{
        .sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
        .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
        .queueFamilyIndex = device.queueFamily,
    };
    VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &device.oneTimePool));
    return device;
}

void destroyDevice(Device& device) {
    vkDestroyCommandPool(device.handle, device.oneTimePool, nullptr);
    vkDestroyDevice(device.handle, nullptr);
    device = {};
}

}  // namespace common
