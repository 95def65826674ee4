// The Vulkan instance (API 1.3) and, with --validation, the Khronos validation layer with
// synchronization validation and a debug messenger that counts what it reports.
// The book creates these in its chapters 1-2 (Instance, with the debug callback).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace common {

struct Instance {
    VkInstance handle = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // only with validation
    bool surfaceMaintenance1 = false;  // VK_EXT_surface_maintenance1 enabled (a window, where offered)
};

// `extensions`: what the presentation target needs (the window system's surface extensions).
// Instance extensions the loader and drivers offer.
bool hasInstanceExtension(const char* name);
Instance createInstance(const char* applicationName, bool validation, std::vector<const char*> extensions);
void destroyInstance(Instance& instance);

// Warnings and errors reported by the validation layer so far in this process.
uint32_t validationMessageCount();

}  // namespace common
