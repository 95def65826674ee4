// VK_CHECK and the two error types that every chapter maps to an exit code.
// Introduced with the book's first Vulkan calls (its vkCheck helper, chapters 1-6).
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>

namespace common {

// Bad command line or bad input (a file, a value out of range): exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Anything else that stops a chapter (a Vulkan error, no display): exit code 1.
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The VkResult's enumerant name, e.g. "VK_ERROR_DEVICE_LOST".
const char* resultName(VkResult result);

[[noreturn]] void throwVkError(VkResult result, const char* expression, const char* file, int line);

}  // namespace common

// Stays on in Release builds: a failed call throws common::Failure naming the call, the file,
// the line and the result. Swapchain results (SUBOPTIMAL, OUT_OF_DATE) are handled where they
// occur (common/wnd/target.cpp), never through this macro.
#define VK_CHECK(expression)                                                         \
    do {                                                                             \
        VkResult vkCheckResult_ = (expression);                                      \
        if (vkCheckResult_ != VK_SUCCESS)                                            \
            ::common::throwVkError(vkCheckResult_, #expression, __FILE__, __LINE__); \
    } while (0)

// The same for a result kept to look at first (VK_NOT_READY, swapchain results): `call` names
// the function it came from, for the message.
#define VK_CHECK_RESULT(result, call)                                                           \
    do {                                                                                        \
        if ((result) != VK_SUCCESS) ::common::throwVkError((result), call, __FILE__, __LINE__); \
    } while (0)
