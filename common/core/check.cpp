// VK_CHECK's reporting: the result's name and where the call was made.
#include "common/core/check.hpp"

#include <string>
#include <string_view>

namespace common {

const char* resultName(VkResult result) {
    switch (result) {
#define NAME(r) \
    case r:     \
        return #r
        NAME(VK_SUCCESS);
        NAME(VK_NOT_READY);
        NAME(VK_TIMEOUT);
        NAME(VK_EVENT_SET);
        NAME(VK_EVENT_RESET);
        NAME(VK_INCOMPLETE);
        NAME(VK_ERROR_OUT_OF_HOST_MEMORY);
        NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY);
        NAME(VK_ERROR_INITIALIZATION_FAILED);
        NAME(VK_ERROR_DEVICE_LOST);
        NAME(VK_ERROR_MEMORY_MAP_FAILED);
        NAME(VK_ERROR_LAYER_NOT_PRESENT);
        NAME(VK_ERROR_EXTENSION_NOT_PRESENT);
        NAME(VK_ERROR_FEATURE_NOT_PRESENT);
        NAME(VK_ERROR_INCOMPATIBLE_DRIVER);
        NAME(VK_ERROR_TOO_MANY_OBJECTS);
        NAME(VK_ERROR_FORMAT_NOT_SUPPORTED);
        NAME(VK_ERROR_FRAGMENTED_POOL);
        NAME(VK_ERROR_UNKNOWN);
        NAME(VK_ERROR_OUT_OF_POOL_MEMORY);
        NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE);
        NAME(VK_ERROR_FRAGMENTATION);
        NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS);
        NAME(VK_PIPELINE_COMPILE_REQUIRED);
        NAME(VK_ERROR_SURFACE_LOST_KHR);
        NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR);
        NAME(VK_SUBOPTIMAL_KHR);
        NAME(VK_ERROR_OUT_OF_DATE_KHR);
        NAME(VK_ERROR_INCOMPATIBLE_DISPLAY_KHR);
        NAME(VK_ERROR_VALIDATION_FAILED_EXT);
#undef NAME
        default:
            return "VK_RESULT_UNKNOWN";
    }
}

// What a result means for the user, for the failures that are not a bug of ours: the GPU gone
// (a driver crash, a GPU reset or hang, an unplugged external GPU) or memory exhausted.
const char* plainWords(VkResult result) {
    switch (result) {
        case VK_ERROR_DEVICE_LOST:
            return "the GPU was lost (driver crash, GPU reset or device removed): ";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY:
            return "out of GPU memory: ";
        case VK_ERROR_OUT_OF_HOST_MEMORY:
            return "out of memory: ";
        default:
            return "";
    }
}

namespace {

// The file name of __FILE__ without its directories (either slash).
std::string baseName(std::string_view file) {
    size_t slash = file.find_last_of("/\\");
    return std::string(slash == std::string_view::npos ? file : file.substr(slash + 1));
}

}  // namespace

void throwVkError(VkResult result, const char* expression, const char* file, int line) {
    std::string message = plainWords(result) + std::string(expression) + " failed with " +
                          resultName(result) + " (" + baseName(file) + ":" + std::to_string(line) + ")";
    throw Failure(message);
}

}  // namespace common
