// The window + swapchain target and the headless target.
#include "common/wnd/target.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>

#if defined(_WIN32)
#include <windows.h>
#endif

#include "common/core/check.hpp"
#include "common/core/stop.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/formats.hpp"

namespace common {
namespace {

// Installed once, when the window opens, before anything else installs its own (Dear ImGui's
// GLFW backend chains to it). It needs nothing but the window, so no pointer to a Target that
// may move; a new size is noticed by pollTarget.
void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

// GLFW loads xinput1_4.dll for gamepads and frees it in glfwTerminate. Wine's xinput1_4 (Wine 8)
// polls HID devices on a thread of its own that can still be running when the library is freed,
// and then faults at exit, in a run that did everything right. Keeping the library loaded until
// the process ends (the DLL pinned) avoids that; on Windows itself it only keeps one DLL mapped.
void keepXInputLoaded() {
#if defined(_WIN32)
    HMODULE module = nullptr;
    if (LoadLibraryW(L"xinput1_4.dll"))
        GetModuleHandleExW(GET_MODULE_HANDLE_EX_FLAG_PIN, L"xinput1_4.dll", &module);
#endif
}

std::string glfwErrorText() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

std::string offeredFormats(const std::vector<VkSurfaceFormatKHR>& formats) {
    std::string names;
    for (const VkSurfaceFormatKHR& f : formats)
        names += (names.empty() ? "" : ", ") + formatName(f.format) + " " + colorSpaceName(f.colorSpace);
    return names;
}

// The first of kPresentFormats the surface offers in the sRGB colour space (or --target-format's).
VkSurfaceFormatKHR chooseSurfaceFormat(const Target& target, const Device& device) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical, target.surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical, target.surface, &count, formats.data()));
    auto offered = [&](VkFormat format) {
        return std::any_of(formats.begin(), formats.end(), [&](const VkSurfaceFormatKHR& f) {
            return f.format == format && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
        });
    };
    if (target.wantedFormat) {
        if (!offered(*target.wantedFormat))
            throw InputError("--target-format " + formatName(*target.wantedFormat) +
                             ": the window surface does not offer it (it offers " + offeredFormats(formats) +
                             ")");
        return {*target.wantedFormat, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    }
    for (VkFormat format : kPresentFormats)
        if (offered(format)) return {format, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    throw Failure("the window surface offers no format this program can draw to (it offers " +
                  offeredFormats(formats) + "; usable: " + presentFormatNames() + " in SRGB_NONLINEAR)");
}

VkFormat chooseOffscreenFormat(const Target& target, const Device& device) {
    auto renderable = [&](VkFormat format) {
        VkFormatProperties properties;
        vkGetPhysicalDeviceFormatProperties(device.physical, format, &properties);
        VkFormatFeatureFlags needed =
            VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
        return (properties.optimalTilingFeatures & needed) == needed;
    };
    if (target.wantedFormat) {
        if (!renderable(*target.wantedFormat))
            throw Failure("--target-format " + formatName(*target.wantedFormat) +
                          ": the device cannot render to and copy from it");
        return *target.wantedFormat;
    }
    // The format a window would most likely get, so headless images match windowed ones.
    for (VkFormat format : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
        if (renderable(format)) return format;
    throw Failure("the device cannot render to an 8-bit sRGB colour image");
}

// Views of the images as `encodedFormat` (see Target::encodedViews), where that differs; named
// after the images ("swapchain image 0 (UNORM view)").
void createEncodedViews(Target& target, const Device& device, bool mutableImages,
                        const std::string& imageName) {
    target.encodedFormat = mutableImages ? withoutSrgb(target.format) : target.format;
    if (target.encodedFormat == target.format) {
        target.encodedViews = target.views;
        return;
    }
    for (size_t i = 0; i < target.images.size(); ++i) {
        target.encodedViews.push_back(
            createImageView(device, target.images[i], target.encodedFormat, VK_IMAGE_ASPECT_COLOR_BIT));
        nameObject(device.handle, target.encodedViews.back(),
                   imageName + " " + std::to_string(i) + " (UNORM view)");
    }
}

void createSwapchain(Target& target, const Device& device) {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physical, target.surface, &caps));
    VkSurfaceFormatKHR surfaceFormat = chooseSurfaceFormat(target, device);

    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {  // the surface takes the swapchain's size: use the framebuffer's
        int width = 0, height = 0;
        glfwGetFramebufferSize(target.window, &width, &height);
        extent = {
            std::clamp(static_cast<uint32_t>(width), caps.minImageExtent.width, caps.maxImageExtent.width),
            std::clamp(static_cast<uint32_t>(height), caps.minImageExtent.height,
                       caps.maxImageExtent.height)};
    }
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount != 0) imageCount = std::min(imageCount, caps.maxImageCount);
    VkCompositeAlphaFlagBitsKHR compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & compositeAlpha))
        compositeAlpha = static_cast<VkCompositeAlphaFlagBitsKHR>(
            caps.supportedCompositeAlpha & ~(caps.supportedCompositeAlpha - 1));  // lowest supported bit

    // FIFO waits for the display's vertical blank and is always there. A benchmark measures the
    // renderer, not the display: MAILBOX (newest frame wins) or IMMEDIATE when offered.
    VkPresentModeKHR presentMode = VK_PRESENT_MODE_FIFO_KHR;
    if (!target.vsync) {
        uint32_t modeCount = 0;
        VK_CHECK(
            vkGetPhysicalDeviceSurfacePresentModesKHR(device.physical, target.surface, &modeCount, nullptr));
        std::vector<VkPresentModeKHR> modes(modeCount);
        VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device.physical, target.surface, &modeCount,
                                                           modes.data()));
        for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR})
            if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) presentMode = wanted;
    }
    // _SRGB images that may also be viewed as _UNORM (Target::encodedViews).
    VkFormat viewFormats[] = {surfaceFormat.format, withoutSrgb(surfaceFormat.format)};
    bool mutableImages = device.swapchainMutableFormat && viewFormats[1] != viewFormats[0];
    VkImageFormatListCreateInfo formatList{.sType = VK_STRUCTURE_TYPE_IMAGE_FORMAT_LIST_CREATE_INFO,
                                           .viewFormatCount = 2,
                                           .pViewFormats = viewFormats};
    VkSwapchainKHR old = target.swapchain;
    VkSwapchainCreateInfoKHR info{
        .sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
        .pNext = mutableImages ? &formatList : nullptr,
        .flags = mutableImages ? VkSwapchainCreateFlagsKHR{VK_SWAPCHAIN_CREATE_MUTABLE_FORMAT_BIT_KHR} : 0,
        .surface = target.surface,
        .minImageCount = imageCount,
        .imageFormat = surfaceFormat.format,
        .imageColorSpace = surfaceFormat.colorSpace,
        .imageExtent = extent,
        .imageArrayLayers = 1,
        // TRANSFER_SRC lets --screenshot copy a swapchain image out.
        .imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                      (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
        .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
        .preTransform = caps.currentTransform,
        .compositeAlpha = compositeAlpha,
        .presentMode = presentMode,
        .clipped = VK_TRUE,
        .oldSwapchain = old,
    };
    VK_CHECK(vkCreateSwapchainKHR(device.handle, &info, nullptr, &target.swapchain));
    nameObject(device.handle, target.swapchain, "swapchain");
    // The old swapchain is retired now (no new image can be acquired from it) but not destroyed:
    // its last images may still be on their way to the screen (Target::Retired).
    if (old != VK_NULL_HANDLE) target.retired.back().swapchain = old;

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(device.handle, target.swapchain, &count, nullptr));
    target.images.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(device.handle, target.swapchain, &count, target.images.data()));
    target.format = surfaceFormat.format;
    target.colorSpace = surfaceFormat.colorSpace;
    target.extent = extent;
    target.presentLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
    for (size_t i = 0; i < target.images.size(); ++i) {
        std::string name = "swapchain image " + std::to_string(i);
        nameObject(device.handle, target.images[i], name);
        target.views.push_back(
            createImageView(device, target.images[i], target.format, VK_IMAGE_ASPECT_COLOR_BIT));
        nameObject(device.handle, target.views.back(), name);
    }
    createEncodedViews(target, device, mutableImages, "swapchain image");
    target.presentedSinceRetiring.assign(target.images.size(), false);
}

void createOffscreen(Target& target, const Device& device) {
    uint32_t limit = device.properties.limits.maxImageDimension2D;
    if (target.requestedExtent.width > limit || target.requestedExtent.height > limit)
        throw InputError("image size " + std::to_string(target.requestedExtent.width) + "x" +
                         std::to_string(target.requestedExtent.height) + " exceeds this device's limit of " +
                         std::to_string(limit));
    constexpr uint32_t kOffscreenImages = 2;  // like a double-buffered swapchain
    target.format = chooseOffscreenFormat(target, device);
    target.extent = target.requestedExtent;
    target.presentLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    // _SRGB images also viewed as _UNORM (Target::encodedViews). The list of the two formats
    // (core in 1.2) lets a driver keep what it can, such as colour compression, for both.
    bool mutableImages = withoutSrgb(target.format) != target.format;
    VkFormat viewFormats[] = {target.format, withoutSrgb(target.format)};
    VkImageFormatListCreateInfo formatList{.sType = VK_STRUCTURE_TYPE_IMAGE_FORMAT_LIST_CREATE_INFO,
                                           .viewFormatCount = 2,
                                           .pViewFormats = viewFormats};
    bool listFormats = mutableImages && device.apiVersion >= VK_API_VERSION_1_2;
    for (uint32_t i = 0; i < kOffscreenImages; ++i) {
        target.offscreen.push_back(createImage(
            device, target.extent, target.format,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
            "offscreen target " + std::to_string(i), 1,
            mutableImages ? VkImageCreateFlags{VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT} : VkImageCreateFlags{0},
            listFormats ? &formatList : nullptr));
        target.images.push_back(target.offscreen.back().handle);
        target.views.push_back(target.offscreen.back().view);
    }
    createEncodedViews(target, device, mutableImages, "offscreen target");
    target.nextOffscreen = 0;
}

void destroyRetired(Target& target, const Device& device, size_t count) {
    for (size_t i = 0; i < count; ++i) {
        for (VkSemaphore semaphore : target.retired[i].semaphores)
            vkDestroySemaphore(device.handle, semaphore, nullptr);
        vkDestroySwapchainKHR(device.handle, target.retired[i].swapchain, nullptr);
    }
    target.retired.erase(target.retired.begin(), target.retired.begin() + std::ptrdiff_t(count));
}

// Without VK_EXT_swapchain_maintenance1: the acquire fence, seen signalled, releases the retired
// swapchains of Target::Retired's rule (none when the image it acquired had not been presented
// since they were retired) and is free for the next acquire. Polled: never waits.
void collectAcquireFence(Target& target, const Device& device) {
    if (!target.acquireFencePending) return;
    VkResult status = vkGetFenceStatus(device.handle, target.acquireFence);
    if (status == VK_NOT_READY) return;
    VK_CHECK_RESULT(status, "vkGetFenceStatus");
    VK_CHECK(vkResetFences(device.handle, 1, &target.acquireFence));
    target.acquireFencePending = false;
    destroyRetired(target, device, target.acquireFenceReleases);
    target.acquireFenceReleases = 0;
}

// VK_EXT_swapchain_maintenance1: the presentations seen done give their fences back, and a retired
// swapchain none of whose presentations is pending goes, with its semaphores.
void collectPresentFences(Target& target, const Device& device) {
    std::erase_if(target.presentFences, [&](const Target::PresentFence& present) {
        if (vkGetFenceStatus(device.handle, present.fence) != VK_SUCCESS) return false;
        VK_CHECK(vkResetFences(device.handle, 1, &present.fence));
        target.spareFences.push_back(present.fence);
        return true;
    });
    std::erase_if(target.retired, [&](const Target::Retired& retired) {
        for (const Target::PresentFence& present : target.presentFences)
            if (present.swapchain == retired.swapchain) return false;
        for (VkSemaphore semaphore : retired.semaphores)
            vkDestroySemaphore(device.handle, semaphore, nullptr);
        vkDestroySwapchainKHR(device.handle, retired.swapchain, nullptr);
        return true;
    });
}

// Destroys what depends on the images. A swapchain survives to become oldSwapchain, and its
// semaphores, which the presentation engine may still wait on, are retired with it.
void releaseImages(Target& target, const Device& device) {
    if (target.encodedViews != target.views)
        for (VkImageView view : target.encodedViews) vkDestroyImageView(device.handle, view, nullptr);
    target.encodedViews.clear();
    if (target.window) {
        target.retired.push_back({VK_NULL_HANDLE, std::move(target.renderFinished)});
        for (VkImageView view : target.views) vkDestroyImageView(device.handle, view, nullptr);
    } else {
        for (VkSemaphore semaphore : target.renderFinished)
            vkDestroySemaphore(device.handle, semaphore, nullptr);
        for (Image& image : target.offscreen) destroyImage(device, image);
        target.offscreen.clear();
    }
    target.renderFinished.clear();
    target.views.clear();
    target.images.clear();
}

}  // namespace

Target openTarget(const Options& options, const char* title) {
    Target target;
    target.requestedExtent = {options.width, options.height};
    target.vsync = !options.benchmark;
    target.wantedFormat = options.targetFormat;
    if (options.headless) return target;

    keepXInputLoaded();
    if (!glfwInit()) throw Failure("cannot open a window (" + glfwErrorText() + "); run with --headless");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throw Failure("GLFW found no Vulkan loader for window surfaces; run with --headless");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan, not OpenGL
    target.window = glfwCreateWindow(static_cast<int>(options.width), static_cast<int>(options.height), title,
                                     nullptr, nullptr);
    if (!target.window) {
        std::string why = glfwErrorText();
        glfwTerminate();
        throw Failure("cannot create a window (" + why + "); run with --headless");
    }
    glfwSetKeyCallback(target.window, onKey);
    return target;
}

std::vector<const char*> targetInstanceExtensions(const Target& target) {
    if (!target.window) return {};
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    std::vector<const char*> extensions(names, names + count);
    // What a device's VK_EXT_swapchain_maintenance1 (present fences) builds on, where offered.
    if (hasInstanceExtension(VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME) &&
        hasInstanceExtension(VK_KHR_GET_SURFACE_CAPABILITIES_2_EXTENSION_NAME)) {
        extensions.push_back(VK_KHR_GET_SURFACE_CAPABILITIES_2_EXTENSION_NAME);
        extensions.push_back(VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME);
    }
    return extensions;
}

void createTargetSurface(Target& target, const Instance& instance) {
    if (!target.window) return;
    VK_CHECK(glfwCreateWindowSurface(instance.handle, target.window, nullptr, &target.surface));
}

void createTargetImages(Target& target, const Device& device) {
    if (target.window) {
        int width = 0, height = 0;
        glfwGetFramebufferSize(target.window, &width, &height);
        target.framebufferSize = {uint32_t(width), uint32_t(height)};
        createSwapchain(target, device);
    } else {
        createOffscreen(target, device);
    }
    for (size_t i = 0; i < target.images.size(); ++i) {
        target.renderFinished.push_back(createSemaphore(device));
        nameObject(device.handle, target.renderFinished.back(),
                   "target image " + std::to_string(i) + " rendered");
    }
    target.resized = false;
}

void requestTargetSize(Target& target, VkExtent2D size) {
    if (target.window) {
        // Goes through the window system; pollTarget sees the new size when it arrives, exactly
        // as when a user drags the window border.
        glfwSetWindowSize(target.window, static_cast<int>(size.width), static_cast<int>(size.height));
    } else {
        target.requestedExtent = size;
        target.resized = true;
    }
}

bool pollTarget(Target& target) {
    if (!target.window) return false;
    glfwPollEvents();
    // Minimised: nothing is visible, so nothing is drawn; sleep until the window comes back (or
    // is closed) instead of rendering frames nobody sees. Where minimising also makes the
    // framebuffer 0x0 (Windows), recreateTargetImages waits the same way.
    while (glfwGetWindowAttrib(target.window, GLFW_ICONIFIED) && !glfwWindowShouldClose(target.window))
        glfwWaitEvents();
    int width = 0, height = 0;
    glfwGetFramebufferSize(target.window, &width, &height);
    if (uint32_t(width) != target.framebufferSize.width || uint32_t(height) != target.framebufferSize.height)
        target.resized = true;
    return glfwWindowShouldClose(target.window);
}

bool acquireTargetImage(Target& target, const Device& device, VkSemaphore imageAvailable,
                        uint32_t* imageIndex) {
    if (target.window) {
        // While swapchains wait to be destroyed (Target::Retired), the acquire gets a fence too.
        VkFence fence = VK_NULL_HANDLE;
        if (!device.swapchainMaintenance1) {
            collectAcquireFence(target, device);
            if (!target.retired.empty() && !target.acquireFencePending) {
                if (target.acquireFence == VK_NULL_HANDLE) {
                    target.acquireFence = createFence(device, false);
                    nameObject(device.handle, target.acquireFence, "acquire fence");
                }
                fence = target.acquireFence;
            }
        }
        VkResult result = vkAcquireNextImageKHR(device.handle, target.swapchain, UINT64_MAX, imageAvailable,
                                                fence, imageIndex);
        if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;  // the fence is untouched
        // Suboptimal still signals the semaphore (and the fence): draw, then recreate.
        if (result != VK_SUBOPTIMAL_KHR) VK_CHECK_RESULT(result, "vkAcquireNextImageKHR");
        if (device.swapchainMaintenance1) {
            collectPresentFences(target, device);
        } else if (fence != VK_NULL_HANDLE) {
            // An image presented since the retirements: once the fence signals, the presentation
            // engine is done with it, and so with every presentation queued before it.
            target.acquireFencePending = true;
            target.acquireFenceReleases =
                target.presentedSinceRetiring[*imageIndex] ? target.retired.size() : 0;
        }
        return true;
    }
    // Headless: images are handed out in turn, and an empty submission signals the semaphore the
    // way the presentation engine would, so the frame waits on it exactly as it does on a window.
    *imageIndex = target.nextOffscreen;
    target.nextOffscreen = (target.nextOffscreen + 1) % static_cast<uint32_t>(target.images.size());
    VkSubmitInfo signal{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .signalSemaphoreCount = 1,
        .pSignalSemaphores = &imageAvailable,
    };
    VK_CHECK(vkQueueSubmit(device.queue, 1, &signal, VK_NULL_HANDLE));
    return true;
}

namespace {

// Waits for `fence` in slices of 50 ms, reading the window's events between them. A close (the
// window's button, Escape) lets the frame finish if it does within common::stopGraceMs() (the run
// then ends at the next frame as always); a frame still running then is cut short at once
// (common::requestStop), so that a closed window ends the run within a second whatever the frame.
void waitReadingEvents(Target& target, const Device& device, VkFence fence) {
    constexpr uint64_t kSlice = 50'000'000;  // ns
    std::optional<std::chrono::steady_clock::time_point> closed;
    for (;;) {
        VkResult result = vkWaitForFences(device.handle, 1, &fence, VK_TRUE, kSlice);
        if (result == VK_SUCCESS) return;
        if (result != VK_TIMEOUT) VK_CHECK_RESULT(result, "vkWaitForFences");
        glfwPollEvents();
        if (!glfwWindowShouldClose(target.window)) continue;
        const auto now = std::chrono::steady_clock::now();
        if (!closed) closed = now;
        if (now - *closed > std::chrono::milliseconds(stopGraceMs())) requestStop(/*now=*/true);
    }
}

}  // namespace

void waitForFrame(Target& target, const Device& device, VkFence frameDone) {
    waitReadingEvents(target, device, frameDone);
}

bool presentTargetImage(Target& target, const Device& device, uint32_t imageIndex, VkFence frameDone) {
    // A present that waited more than 100 ms: frames are long, and the next one is waited for here,
    // where the window's events can be read (a present that waits reads none).
    const auto start = std::chrono::steady_clock::now();
    if (target.window && frameDone != VK_NULL_HANDLE && target.lastPresentMs > 100.0)
        waitReadingEvents(target, device, frameDone);
    bool current = presentImage(target, device, imageIndex);
    if (target.window)  // the wait for the frame counted in
        target.lastPresentMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return current && !target.resized;
}

bool presentImage(Target& target, const Device& device, uint32_t imageIndex) {
    if (target.window) {
        const auto presentStart = std::chrono::steady_clock::now();
        // VK_EXT_swapchain_maintenance1: a fence that says when this presentation is done.
        VkSwapchainPresentFenceInfoEXT fenceInfo{.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_PRESENT_FENCE_INFO_EXT,
                                                 .swapchainCount = 1};
        if (device.swapchainMaintenance1) {
            VkFence fence = VK_NULL_HANDLE;
            if (target.spareFences.empty()) {
                fence = createFence(device, false);
                nameObject(device.handle, fence, "present fence");
            } else {
                fence = target.spareFences.back();
                target.spareFences.pop_back();
            }
            target.presentFences.push_back({fence, target.swapchain});
            fenceInfo.pFences = &target.presentFences.back().fence;
        }
        VkPresentInfoKHR info{
            .sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
            .pNext = device.swapchainMaintenance1 ? &fenceInfo : nullptr,
            .waitSemaphoreCount = 1,
            .pWaitSemaphores = &target.renderFinished[imageIndex],
            .swapchainCount = 1,
            .pSwapchains = &target.swapchain,
            .pImageIndices = &imageIndex,
        };
        VkResult result = vkQueuePresentKHR(device.queue, &info);
        target.lastPresentMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - presentStart)
                .count();
        target.presentedSinceRetiring[imageIndex] = true;
        if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
        VK_CHECK_RESULT(result, "vkQueuePresentKHR");
        return true;
    }
    // Headless: nothing to show, but the semaphore is consumed as a present would consume it.
    // The batch is empty, so no stage of it waits: BOTTOM_OF_PIPE (ALL_COMMANDS would say the
    // same here, but is the mask the best-practices checks flag for stalling real work).
    VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
    VkSubmitInfo consume{
        .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
        .waitSemaphoreCount = 1,
        .pWaitSemaphores = &target.renderFinished[imageIndex],
        .pWaitDstStageMask = &waitStage,
    };
    VK_CHECK(vkQueueSubmit(device.queue, 1, &consume, VK_NULL_HANDLE));
    return true;
}

bool recreateTargetImages(Target& target, const Device& device) {
    if (target.window) {
        int width = 0, height = 0;
        glfwGetFramebufferSize(target.window, &width, &height);
        while ((width == 0 || height == 0) && !glfwWindowShouldClose(target.window)) {
            glfwWaitEvents();  // minimised: sleep until the window comes back
            glfwGetFramebufferSize(target.window, &width, &height);
        }
        if (glfwWindowShouldClose(target.window)) return false;
    }
    // The old images' views, framebuffers and the command buffers that use them are the GPU's
    // until it is idle; the presentation engine's use of the old swapchain is not covered by
    // this wait (Target::Retired).
    VK_CHECK(vkDeviceWaitIdle(device.handle));
    releaseImages(target, device);
    createTargetImages(target, device);
    return true;
}

void destroyTargetImages(Target& target, const Device& device) {
    // At the end of a run, after the device is idle: the queue has processed every presentation
    // request (the wait covers the queue), and nothing will be presented any more.
    releaseImages(target, device);
    if (!target.presentFences.empty()) {  // maintenance1: the last presentations, done
        std::vector<VkFence> fences;
        for (const Target::PresentFence& present : target.presentFences) fences.push_back(present.fence);
        // Not VK_CHECK: after a lost device this returns VK_ERROR_DEVICE_LOST, and teardown goes on.
        vkWaitForFences(device.handle, uint32_t(fences.size()), fences.data(), VK_TRUE, UINT64_MAX);
        for (VkFence fence : fences) target.spareFences.push_back(fence);
        target.presentFences.clear();
    }
    for (VkFence fence : target.spareFences) vkDestroyFence(device.handle, fence, nullptr);
    target.spareFences.clear();
    if (target.acquireFencePending)  // not VK_CHECK: teardown goes on after a lost device
        vkWaitForFences(device.handle, 1, &target.acquireFence, VK_TRUE, UINT64_MAX);
    vkDestroyFence(device.handle, target.acquireFence, nullptr);
    target.acquireFence = VK_NULL_HANDLE;
    target.acquireFencePending = false;
    if (target.swapchain != VK_NULL_HANDLE) vkDestroySwapchainKHR(device.handle, target.swapchain, nullptr);
    target.swapchain = VK_NULL_HANDLE;
    // Without maintenance1, swapchains still retired have had no acquire to tell: after the
    // device wait, with nothing presented since and no swapchain left in use, they go as the
    // current one did (as Khronos' swapchain_recreation sample does at its end).
    destroyRetired(target, device, target.retired.size());
}

void destroyTargetSurface(Target& target, const Instance& instance) {
    if (target.surface != VK_NULL_HANDLE) vkDestroySurfaceKHR(instance.handle, target.surface, nullptr);
    target.surface = VK_NULL_HANDLE;
}

void closeTarget(Target& target) {
    if (target.window) {
        glfwDestroyWindow(target.window);
        glfwTerminate();
    }
    target.window = nullptr;
}

std::vector<VkFramebuffer> createTargetFramebuffers(const Device& device, VkRenderPass renderPass,
                                                    const Target& target) {
    std::vector<VkFramebuffer> framebuffers(target.views.size());
    for (size_t i = 0; i < target.views.size(); ++i) {
        VkFramebufferCreateInfo info{
            .sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
            .renderPass = renderPass,
            .attachmentCount = 1,
            .pAttachments = &target.views[i],
            .width = target.extent.width,
            .height = target.extent.height,
            .layers = 1,
        };
        VK_CHECK(vkCreateFramebuffer(device.handle, &info, nullptr, &framebuffers[i]));
        nameObject(device.handle, framebuffers[i], "target image " + std::to_string(i));
    }
    return framebuffers;
}

void destroyFramebuffers(const Device& device, std::vector<VkFramebuffer>& framebuffers) {
    for (VkFramebuffer framebuffer : framebuffers) vkDestroyFramebuffer(device.handle, framebuffer, nullptr);
    framebuffers.clear();
}

}  // namespace common
