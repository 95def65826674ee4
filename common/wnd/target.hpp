// Where a chapter's frames go: a GLFW window with a swapchain, or -- with --headless -- a set of
// offscreen colour images of the same format that behave like one. Both are driven by the same
// calls, so a chapter's frame loop has no headless special case:
//
//   openTarget -> createInstance(targetInstanceExtensions) -> createTargetSurface -> createDevice
//   -> createTargetImages; per frame: pollTarget, acquireTargetImage, (record, submit),
//   presentTargetImage, recreateTargetImages when either says so; teardown in reverse.
// A Target is presentation only: how many frames a run draws, and when --resize strikes, are run
// control (common/app/run_control.hpp).
//
// The book's Window, Surface and SwapChain (chapters 1-5).
#pragma once

#include <GLFW/glfw3.h>
#include <vulkan/vulkan.h>

#include <optional>
#include <vector>

#include "common/core/options.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/instance.hpp"

namespace common {

struct Target {
    GLFWwindow* window = nullptr;  // nullptr: headless
    double lastPresentMs =
        0.0;  // how long the last presentTargetImage waited (for its frame, then to present)
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    std::vector<Image> offscreen;  // headless: the images a swapchain would own

    // The images' format: what the window system offers (common/vk/formats.hpp lists the ones we
    // take), or --target-format's. A pass that writes the images sRGB-encodes itself unless
    // common::encodesSrgb(format).
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR colorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkExtent2D extent{};
    // The layout an image must be in when handed to presentTargetImage: PRESENT_SRC_KHR for a
    // swapchain, TRANSFER_SRC_OPTIMAL for headless images (they are only ever copied out).
    VkImageLayout presentLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    std::vector<VkImage> images;
    std::vector<VkImageView> views;
    // The same images seen without the hardware's sRGB encoding (an _SRGB format viewed as its
    // _UNORM twin), where the images allow it: Dear ImGui's colours are sRGB values meant to be
    // blended as they are, and the GUI pass draws through these. Otherwise the same as `views`.
    VkFormat encodedFormat = VK_FORMAT_UNDEFINED;
    std::vector<VkImageView> encodedViews;
    // Signalled when drawing into image i is done and waited on by its presentation. One per
    // image, not per frame in flight: a frame's semaphore could otherwise be signalled again
    // while the presentation engine still waits on it.
    std::vector<VkSemaphore> renderFinished;

    bool resized = false;          // the window or the requested size changed since the images were made
    VkExtent2D requestedExtent{};  // headless: size of the images; window: size asked for
    VkExtent2D framebufferSize{};  // window: the framebuffer size the swapchain was made for
    std::optional<VkFormat> wantedFormat;  // --target-format
    uint32_t nextOffscreen = 0;
    bool vsync = true;  // false with --benchmark: MAILBOX or IMMEDIATE when the surface offers one

    // A swapchain replaced by a new one, and its renderFinished semaphores: the presentation
    // engine may still be presenting its images and waiting on those semaphores, which no
    // command-buffer fence or device wait tells (VUID-vkDestroySwapchainKHR-swapchain-01282). With
    // VK_EXT_swapchain_maintenance1 each presentation signals a fence of its own, and a retired
    // swapchain goes once the fences of all its presentations have signalled. Without it, through
    // an image of the new swapchain that was presented and is acquired again: presentation
    // requests on one queue complete in order, so once the presentation engine is done with that
    // image, every earlier presentation, the old swapchain's included, is done too. Not when
    // vkAcquireNextImageKHR hands back the image's index -- the image may still be on its way to
    // the screen -- but when that acquire's fence signals (vkAcquireNextImageKHR's notes in the
    // specification; Khronos' swapchain_recreation sample). The fence is polled, never waited on.
    struct Retired {
        VkSwapchainKHR swapchain = VK_NULL_HANDLE;
        std::vector<VkSemaphore> semaphores;
    };
    std::vector<Retired> retired;
    std::vector<bool> presentedSinceRetiring;  // per image of the current swapchain
    VkFence acquireFence = VK_NULL_HANDLE;     // given to acquires while swapchains are retired
    bool acquireFencePending = false;          // given to an acquire, not seen signalled yet
    size_t acquireFenceReleases = 0;           // its signal releases retired[0 .. this)
    struct PresentFence {
        VkFence fence = VK_NULL_HANDLE;
        VkSwapchainKHR swapchain = VK_NULL_HANDLE;
    };
    std::vector<PresentFence> presentFences;  // presentations not yet seen done (maintenance1)
    std::vector<VkFence> spareFences;
};

// Opens the window (or nothing, headless) described by the command line.
Target openTarget(const Options& options, const char* title);
// Instance extensions the target needs (the window system's surface extensions).
std::vector<const char*> targetInstanceExtensions(const Target& target);
void createTargetSurface(Target& target, const Instance& instance);
// The swapchain, or the headless images, at the current size; throws InputError when a headless
// size exceeds the device's limit.
void createTargetImages(Target& target, const Device& device);

// Processes window events (sleeping while the window is minimised). Returns true when the
// window asks to close.
bool pollTarget(Target& target);
// Asks for a new size, as a user dragging the window border would (--resize): the window is
// resized through the window system; headless images are remade at the next acquire.
void requestTargetSize(Target& target, VkExtent2D size);
// Gets the next image to draw into; `imageAvailable` is signalled when it may be written.
// Returns false when the target is out of date: call recreateTargetImages and try again.
bool acquireTargetImage(Target& target, const Device& device, VkSemaphore imageAvailable,
                        uint32_t* imageIndex);
// Presents image `imageIndex` once its renderFinished semaphore is signalled. Returns false when
// the target must be recreated (resized, out of date or suboptimal). `frameDone`, the fence of
// the frame that drew the image: when the last present waited long for its frame (lavapipe
// presents only a finished image), the frame is waited for first, reading the window's events
// meanwhile, so that a window closed during a long frame stops the run (common/core/stop.hpp).
bool presentTargetImage(Target& target, const Device& device, uint32_t imageIndex,
                        VkFence frameDone = VK_NULL_HANDLE);
// In a window: waits for `frameDone` reading the window's events meanwhile, as presentTargetImage
// does after a long present (a close during a long frame ends the run; chapter-20's main thread).
void waitForFrame(Target& target, const Device& device, VkFence frameDone);
// The presentation alone: false when the swapchain is out of date or suboptimal. It reads nothing
// that the window's events write (no GLFW call, not `resized`): chapter-20 presents from a thread
// of its own while the main thread reads the events.
bool presentImage(Target& target, const Device& device, uint32_t imageIndex);
// Waits for the device, then rebuilds images at the new size. A minimised window (zero-size
// framebuffer) is waited out. Returns false if the window was closed while waiting.
bool recreateTargetImages(Target& target, const Device& device);

void destroyTargetImages(Target& target, const Device& device);

// One framebuffer per target image, for a render pass whose only attachment is that image
// (chapter-10's lighting pass; chapter-06 writes the same out, as the chapter that teaches it).
std::vector<VkFramebuffer> createTargetFramebuffers(const Device& device, VkRenderPass renderPass,
                                                    const Target& target);
void destroyFramebuffers(const Device& device, std::vector<VkFramebuffer>& framebuffers);
void destroyTargetSurface(Target& target, const Instance& instance);
void closeTarget(Target& target);

}  // namespace common
