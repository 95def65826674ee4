// VK_EXT_debug_utils names and labels (debug_names.hpp).
#include "common/vk/debug_names.hpp"

namespace common {
namespace {

struct DebugUtils {
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel = nullptr;
};
DebugUtils gDebugUtils;

}  // namespace

void loadDebugNames(VkInstance instance, bool enabled) {
    gDebugUtils = {};
    if (!enabled) return;
    gDebugUtils.setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
    gDebugUtils.beginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdBeginDebugUtilsLabelEXT"));
    gDebugUtils.endLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance, "vkCmdEndDebugUtilsLabelEXT"));
    if (!gDebugUtils.setObjectName || !gDebugUtils.beginLabel || !gDebugUtils.endLabel) gDebugUtils = {};
}

bool debugNamesEnabled() {
    return gDebugUtils.setObjectName != nullptr;
}

void setObjectName(VkDevice device, VkObjectType type, uint64_t handle, const std::string& name) {
    if (!gDebugUtils.setObjectName) return;
    VkDebugUtilsObjectNameInfoEXT info{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT,
        .objectType = type,
        .objectHandle = handle,
        .pObjectName = name.c_str(),
    };
    gDebugUtils.setObjectName(device, &info);
}

void beginLabel(VkCommandBuffer cmd, const std::string& name) {
    if (!gDebugUtils.beginLabel) return;
    VkDebugUtilsLabelEXT label{.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT, .pLabelName = name.c_str()};
    gDebugUtils.beginLabel(cmd, &label);
}

void endLabel(VkCommandBuffer cmd) {
    if (gDebugUtils.endLabel) gDebugUtils.endLabel(cmd);
}

}  // namespace common
