// VK_LAYER_VKBOOK_fault_injection: a Vulkan layer that makes one chosen call fail the way a real
// GPU fails -- out of memory, or lost -- so the tests can check that every chapter then stops with
// a clear error instead of hanging or crashing. Lavapipe never runs out of memory or loses its
// device, so the failure has to be injected, and a layer is where the Vulkan loader lets us do it
// without touching the chapters (serious renderers test their error paths the same way).
//
// VKBOOK_FAULT=<call>:<n> fails the n-th call (counting from 1) of <call>:
//   vkAllocateMemory                  -> VK_ERROR_OUT_OF_DEVICE_MEMORY (that call only)
//   vkCreateImage, vkCreateBuffer     -> VK_ERROR_OUT_OF_HOST_MEMORY (that call only)
//   vkCreateGraphicsPipelines, vkCreateComputePipelines
//                                     -> VK_ERROR_OUT_OF_DEVICE_MEMORY (that call only; every
//                                        pipeline it was to make is VK_NULL_HANDLE)
//   vkQueueSubmit, vkQueueSubmit2, vkWaitForFences, vkGetFenceStatus, vkDeviceWaitIdle,
//   vkQueueWaitIdle, vkAcquireNextImageKHR, vkQueuePresentKHR, vkGetQueryPoolResults
//                                     -> VK_ERROR_DEVICE_LOST, and from then on every one of these
//                                        calls on that device returns VK_ERROR_DEVICE_LOST too, as
//                                        after a real device loss (a wait returns at once: no hang).
// A failed call is not passed down, so the layers below (validation) and the driver never see it
// and keep a consistent picture. VKBOOK_FAULT_TRACE=1 prints each counted call, to choose n.
//
// It also makes the device look older or poorer than it is, as a reader's may be:
//   VKBOOK_DEVICE_API=1.2 (1.1, 1.0) the physical device reports that Vulkan version;
//   VKBOOK_HIDE=NAME[,NAME...]      hides device extensions (VK_KHR_dynamic_rendering, ...),
//                                   formats (D32_SFLOAT, B8G8R8A8_SRGB, ... : no features, and not
//                                   among a surface's formats) and the features scalarBlockLayout,
//                                   bufferDeviceAddress, shaderInt64, multiDrawIndirect,
//                                   drawIndirectFirstInstance, geometryShader and depthClamp.
//   VKBOOK_HEAP_MIB=<n>             reports each device-local memory heap as at most n MiB (a GPU
//                                   smaller than this machine's memory, which lavapipe reports).
//   VKBOOK_MAX_COMPUTE_GROUPS=<n>   reports maxComputeWorkGroupCount[0] as n (a small device's
//                                   dispatch limit, met by a small mesh).
//   VKBOOK_MAX_ALLOCATIONS=<n>      reports maxMemoryAllocationCount as n (4096 on many Windows
//                                   drivers; lavapipe has no limit).
//   VKBOOK_EMULATE=swapchain_maintenance1  offers VK_EXT_swapchain_maintenance1 (lavapipe 22.3 has
//                                   none) and carries out its present fences: the fence of a
//                                   presentation is signalled by an empty submission right after
//                                   it (queue order: after the work it waited for), so the code
//                                   that retires swapchains by present fences runs here too.
//                                   VK_EXT_surface_maintenance1, which it builds on, is offered by
//                                   this layer's manifest and taken out before the driver sees it.
//   VKBOOK_HIDE_LATER=FORMAT[,...]  hides those formats from a surface's formats once a swapchain
//                                   has been made: the window moved to another screen, whose
//                                   formats differ, and the next swapchain takes another format.
// Only what the application asks of the physical device changes: the layers below still see the
// real device, so validation checks what the application then does against what it enables.
//
// And it checks one rule no validation layer can (VUID-vkDestroySwapchainKHR-swapchain-01282):
// a swapchain is destroyed only once the presentation engine is done with its images. Returning
// from vkQueuePresentKHR or vkDeviceWaitIdle does not say so; what does, for a swapchain retired
// by a newer one, is that an image of a newer swapchain presented after the retirement has been
// acquired again and a wait on that acquire completed -- its fence seen signalled, or a
// submission that waited on its semaphore seen done -- or (VK_EXT_swapchain_maintenance1) the
// fences of all its presentations seen signalled. At the end of a run, without present fences,
// no more can be known than a device wait with nothing presented since: that lets the current
// swapchain go, and the retired ones once no current one is left. A destruction that breaks the
// rule prints "VK_LAYER_VKBOOK_fault_injection: vkDestroySwapchainKHR: ..." (a test's empty
// stderr then fails); after a device loss nothing is checked.
// Otherwise the layer prints nothing. It is an implicit layer that is only enabled when
// VKBOOK_FAULT_LAYER=1 (see its manifest in tests/reliability/fault.cmake): the loader reports layers enabled
// through VK_INSTANCE_LAYERS as a warning to the debug messenger, which --validation would count.
//
// The layer interface (docs: the Vulkan loader's LoaderLayerInterface.md): the loader asks for
// vkNegotiateLoaderLayerInterfaceVersion, which hands back our vkGetInstanceProcAddr and
// vkGetDeviceProcAddr; in vkCreateInstance / vkCreateDevice each layer finds the next one's
// GetProcAddr in the create info's pNext chain (VkLayerInstanceCreateInfo, VkLayerDeviceCreateInfo).
#include <vulkan/vk_layer.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "../layer_common.hpp"

namespace {

using layer::dispatchKey;
using layer::findLinkInfo;

// ---- Which call fails -------------------------------------------------------------------------

struct Fault {
    std::string call;  // e.g. "vkQueueSubmit2"; empty: inject nothing
    unsigned long long nth = 0;
    bool trace = false;  // VKBOOK_FAULT_TRACE=1: print every counted call (to choose n)
    std::unordered_map<std::string, unsigned long long> calls;  // how often each call was made
};

Fault parseFault() {
    Fault f;
    const char* trace = std::getenv("VKBOOK_FAULT_TRACE");
    f.trace = trace != nullptr && std::strcmp(trace, "1") == 0;
    const char* spec = std::getenv("VKBOOK_FAULT");
    if (spec == nullptr || *spec == '\0') return f;
    const char* colon = std::strrchr(spec, ':');
    char* end = nullptr;
    unsigned long long n = colon ? std::strtoull(colon + 1, &end, 10) : 0;
    if (colon == nullptr || colon == spec || end == colon + 1 || *end != '\0' || n == 0) {
        std::fprintf(stderr, "VK_LAYER_VKBOOK_fault_injection: VKBOOK_FAULT='%s' is not <call>:<n>\n", spec);
        return f;
    }
    f.call.assign(spec, colon);
    f.nth = n;
    return f;
}

// A plain static, not a leaked pointer: the loader unloads the layer at vkDestroyInstance, and
// memory that only the unloaded library pointed to would be reported by LeakSanitizer.
Fault& fault() {
    static Fault parsed = parseFault();
    return parsed;
}

// Counts a call of `call` (the caller holds gLock); true when it is the one to fail.
bool failsNow(const char* call) {
    Fault& f = fault();
    unsigned long long n = ++f.calls[call];
    if (f.trace) std::fprintf(stderr, "VK_LAYER_VKBOOK_fault_injection: %s #%llu\n", call, n);
    return n == f.nth && f.call == call;
}

// ---- Per-instance and per-device state ---------------------------------------------------------

struct InstanceData {
    VkInstance handle = VK_NULL_HANDLE;
    PFN_vkGetInstanceProcAddr next = nullptr;  // the next layer's (or the loader's) GetProcAddr
    // The next layer's physical-device queries this layer answers, looked up once, when the
    // instance is made. Not later: with no layer below this one, `next` is the loader's, which
    // answers from the instance's dispatch table -- by then the top of the chain, this layer's own
    // functions, which would call themselves until the stack runs out.
    std::unordered_map<std::string, PFN_vkVoidFunction> calls;
};

// The physical-device queries InstanceData::calls holds (a name ending in KHR: the extension's
// form, used where the core one is missing).
constexpr const char* kInstanceCalls[] = {
    "vkGetPhysicalDeviceProperties",
    "vkGetPhysicalDeviceProperties2",
    "vkGetPhysicalDeviceProperties2KHR",
    "vkGetPhysicalDeviceMemoryProperties",
    "vkGetPhysicalDeviceMemoryProperties2",
    "vkGetPhysicalDeviceMemoryProperties2KHR",
    "vkGetPhysicalDeviceFeatures",
    "vkGetPhysicalDeviceFeatures2",
    "vkGetPhysicalDeviceFeatures2KHR",
    "vkEnumerateDeviceExtensionProperties",
    "vkGetPhysicalDeviceFormatProperties",
    "vkGetPhysicalDeviceFormatProperties2",
    "vkGetPhysicalDeviceFormatProperties2KHR",
    "vkGetPhysicalDeviceSurfaceFormatsKHR",
};

// What the layer knows of a swapchain, to check when it may be destroyed.
struct SwapchainState {
    bool retired = false;                      // a newer swapchain was made from it (oldSwapchain)
    bool released = false;                     // retired, and the presentation engine is done with it
    std::vector<VkSwapchainKHR> olderRetired;  // retired swapchains alive when this one was made
    std::vector<bool> presented;               // per image: presented (after all of olderRetired retired)
    std::vector<VkFence> presentFences;        // maintenance1: its presentations' fences not seen signalled
    uint64_t presentsWithoutFence = 0;         // presentations no fence reports on
};
// An acquire of an image presented after `releases` were retired: once a wait on it is seen
// complete, they are released.
struct AcquireWait {
    VkFence fence = VK_NULL_HANDLE;          // the acquire's fence
    VkSemaphore semaphore = VK_NULL_HANDLE;  // the acquire's semaphore ...
    bool waited = false;                     // ... waited on by a submission ...
    VkFence submitFence = VK_NULL_HANDLE;    // ... with this fence
    std::vector<VkSwapchainKHR> releases;
};

struct DeviceData {
    PFN_vkGetDeviceProcAddr getProcAddr = nullptr;  // the next layer's
    bool lost = false;         // once a loss is injected, everything that can report one does
    uint64_t allocations = 0;  // live VkDeviceMemory objects, for VKBOOK_MAX_ALLOCATIONS
    std::unordered_map<VkSwapchainKHR, SwapchainState> swapchains;
    std::vector<AcquireWait> acquireWaits;
    bool idleSincePresent = true;  // a device or queue wait returned since the last presentation
    struct {                       // the next layer's functions that we call down to
        PFN_vkDestroyDevice destroyDevice;
        PFN_vkAllocateMemory allocateMemory;
        PFN_vkFreeMemory freeMemory;
        PFN_vkCreateImage createImage;
        PFN_vkCreateBuffer createBuffer;
        PFN_vkCreateGraphicsPipelines createGraphicsPipelines;
        PFN_vkCreateComputePipelines createComputePipelines;
        PFN_vkQueueSubmit queueSubmit;
        PFN_vkQueueSubmit2 queueSubmit2;
        PFN_vkWaitForFences waitForFences;
        PFN_vkGetFenceStatus getFenceStatus;
        PFN_vkDeviceWaitIdle deviceWaitIdle;
        PFN_vkQueueWaitIdle queueWaitIdle;
        PFN_vkGetQueryPoolResults getQueryPoolResults;
        PFN_vkAcquireNextImageKHR acquireNextImage;  // null without VK_KHR_swapchain
        PFN_vkQueuePresentKHR queuePresent;
        PFN_vkCreateSwapchainKHR createSwapchain;
        PFN_vkDestroySwapchainKHR destroySwapchain;
    } next{};
};

std::mutex gLock;
std::unordered_map<void*, InstanceData> gInstances;
std::unordered_map<void*, DeviceData> gDevices;

InstanceData& instanceData(const void* handle) {
    std::lock_guard lock(gLock);
    return gInstances.at(dispatchKey(handle));
}

// unordered_map never moves its elements, so the reference stays good until the device is destroyed.
DeviceData& deviceData(const void* handle) {
    std::lock_guard lock(gLock);
    return gDevices.at(dispatchKey(handle));
}

// VK_ERROR_DEVICE_LOST when the device is lost or `call` is the one to lose it; else VK_SUCCESS,
// and the caller passes the call down.
VkResult deviceLoss(DeviceData& device, const char* call) {
    std::lock_guard lock(gLock);
    if (failsNow(call)) device.lost = true;
    return device.lost ? VK_ERROR_DEVICE_LOST : VK_SUCCESS;
}

// ---- The device as the application is to see it -------------------------------------------------

struct Profile {
    bool maintenance1 = false;  // emulate VK_EXT_swapchain_maintenance1
    uint32_t apiVersion = 0;    // 0: the device's own
    std::vector<std::string> hidden;
    std::vector<std::string> hiddenLater;  // formats hidden from surfaces once a swapchain exists
    unsigned long long heapMib = 0;        // 0: the device's own heap sizes
    uint32_t maxAllocations = 0;           // 0: the device's own maxMemoryAllocationCount
    uint32_t maxComputeGroups = 0;         // 0: the device's own maxComputeWorkGroupCount[0]
};

const std::unordered_map<std::string, VkFormat>& formatNames() {
    static const std::unordered_map<std::string, VkFormat> names = {
        {"D32_SFLOAT", VK_FORMAT_D32_SFLOAT},
        {"X8_D24_UNORM_PACK32", VK_FORMAT_X8_D24_UNORM_PACK32},
        {"B8G8R8A8_SRGB", VK_FORMAT_B8G8R8A8_SRGB},
        {"R8G8B8A8_SRGB", VK_FORMAT_R8G8B8A8_SRGB},
        {"B8G8R8A8_UNORM", VK_FORMAT_B8G8R8A8_UNORM},
        {"R8G8B8A8_UNORM", VK_FORMAT_R8G8B8A8_UNORM},
        {"A2R10G10B10_UNORM_PACK32", VK_FORMAT_A2R10G10B10_UNORM_PACK32},
        {"A2B10G10R10_UNORM_PACK32", VK_FORMAT_A2B10G10R10_UNORM_PACK32},
    };
    return names;
}

// "A,B,C" -> {"A", "B", "C"}; an unset or empty variable -> {}.
std::vector<std::string> commaList(const char* value) {
    std::vector<std::string> names;
    if (value == nullptr || *value == '\0') return names;
    std::string list = value;
    for (size_t start = 0; start <= list.size();) {
        size_t comma = list.find(',', start);
        if (comma == std::string::npos) comma = list.size();
        names.push_back(list.substr(start, comma - start));
        start = comma + 1;
    }
    return names;
}

Profile parseProfile() {
    Profile p;
    if (const char* emulate = std::getenv("VKBOOK_EMULATE"); emulate && *emulate) {
        if (std::strcmp(emulate, "swapchain_maintenance1") == 0)
            p.maintenance1 = true;
        else
            std::fprintf(
                stderr,
                "VK_LAYER_VKBOOK_fault_injection: VKBOOK_EMULATE='%s' is not swapchain_maintenance1\n",
                emulate);
    }
    if (const char* api = std::getenv("VKBOOK_DEVICE_API"); api && *api) {
        if (std::strcmp(api, "1.0") == 0)
            p.apiVersion = VK_API_VERSION_1_0;
        else if (std::strcmp(api, "1.1") == 0)
            p.apiVersion = VK_API_VERSION_1_1;
        else if (std::strcmp(api, "1.2") == 0)
            p.apiVersion = VK_API_VERSION_1_2;
        else
            std::fprintf(stderr,
                         "VK_LAYER_VKBOOK_fault_injection: VKBOOK_DEVICE_API='%s' is not 1.0, 1.1 or 1.2\n",
                         api);
    }
    if (const char* heap = std::getenv("VKBOOK_HEAP_MIB"); heap && *heap)
        p.heapMib = std::strtoull(heap, nullptr, 10);
    if (const char* count = std::getenv("VKBOOK_MAX_ALLOCATIONS"); count && *count)
        p.maxAllocations = uint32_t(std::strtoul(count, nullptr, 10));
    if (const char* groups = std::getenv("VKBOOK_MAX_COMPUTE_GROUPS"); groups && *groups)
        p.maxComputeGroups = uint32_t(std::strtoul(groups, nullptr, 10));
    for (const std::string& name : commaList(std::getenv("VKBOOK_HIDE"))) {
        if (!name.starts_with("VK_") && !formatNames().count(name) && name != "scalarBlockLayout" &&
            name != "geometryShader" && name != "depthClamp" && name != "bufferDeviceAddress" &&
            name != "shaderInt64" && name != "multiDrawIndirect" && name != "drawIndirectFirstInstance")
            std::fprintf(stderr,
                         "VK_LAYER_VKBOOK_fault_injection: VKBOOK_HIDE names '%s', neither an extension "
                         "nor a format it knows\n",
                         name.c_str());
        if (!name.empty()) p.hidden.push_back(name);
    }
    for (const std::string& name : commaList(std::getenv("VKBOOK_HIDE_LATER"))) {
        if (formatNames().count(name))
            p.hiddenLater.push_back(name);
        else
            std::fprintf(
                stderr,
                "VK_LAYER_VKBOOK_fault_injection: VKBOOK_HIDE_LATER names '%s', not a format it knows\n",
                name.c_str());
    }
    return p;
}

const Profile& profile() {
    static const Profile parsed = parseProfile();
    return parsed;
}

bool hidden(const char* name) {
    for (const std::string& h : profile().hidden)
        if (h == name) return true;
    return false;
}

bool named(const std::vector<std::string>& names, VkFormat format) {
    for (const std::string& h : names) {
        auto found = formatNames().find(h);
        if (found != formatNames().end() && found->second == format) return true;
    }
    return false;
}

bool hidden(VkFormat format) {
    return named(profile().hidden, format);
}

// Set once any device has made a swapchain (VKBOOK_HIDE_LATER).
bool gSwapchainMade = false;

// The extensions this layer answers for itself: never passed down.
bool ours(const char* extension) {
    return std::strcmp(extension, VK_EXT_SURFACE_MAINTENANCE_1_EXTENSION_NAME) == 0 ||
           std::strcmp(extension, VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME) == 0;
}

std::vector<const char*> withoutOurs(const char* const* names, uint32_t count) {
    std::vector<const char*> kept;
    for (uint32_t i = 0; i < count; ++i)
        if (!ours(names[i])) kept.push_back(names[i]);
    return kept;
}

// Unlinks the structure of `type` from a pNext chain (the chain is the application's; it is
// linked back by the caller's Relink when the call returns). Returns it, or nullptr.
struct Unlinked {
    VkBaseOutStructure* previous = nullptr;
    VkBaseOutStructure* found = nullptr;
    ~Unlinked() {
        if (previous && found) previous->pNext = found;
    }
};
void unlink(void* head, VkStructureType type, Unlinked& out) {
    for (auto* s = static_cast<VkBaseOutStructure*>(head); s && s->pNext; s = s->pNext)
        if (s->pNext->sType == type) {
            out.previous = s;
            out.found = s->pNext;
            s->pNext = s->pNext->pNext;
            return;
        }
}

// ---- Instance and device creation: linking into the chain ---------------------------------------

VKAPI_ATTR VkResult VKAPI_CALL createInstance(const VkInstanceCreateInfo* createInfo,
                                              const VkAllocationCallbacks* allocator, VkInstance* instance) {
    auto* link = findLinkInfo<VkLayerInstanceCreateInfo>(createInfo->pNext,
                                                         VK_STRUCTURE_TYPE_LOADER_INSTANCE_CREATE_INFO);
    if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr next = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;  // the next layer finds its own link
    auto create = reinterpret_cast<PFN_vkCreateInstance>(next(VK_NULL_HANDLE, "vkCreateInstance"));
    VkInstanceCreateInfo info = *createInfo;
    std::vector<const char*> extensions =
        withoutOurs(info.ppEnabledExtensionNames, info.enabledExtensionCount);
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result = create(&info, allocator, instance);
    if (result != VK_SUCCESS) return result;
    InstanceData data{*instance, next, {}};
    for (const char* name : kInstanceCalls) data.calls[name] = next(*instance, name);
    std::lock_guard lock(gLock);
    gInstances[dispatchKey(*instance)] = std::move(data);
    return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL destroyInstance(VkInstance instance, const VkAllocationCallbacks* allocator) {
    if (instance == VK_NULL_HANDLE) return;
    InstanceData data = instanceData(instance);
    {
        std::lock_guard lock(gLock);
        gInstances.erase(dispatchKey(instance));
    }
    reinterpret_cast<PFN_vkDestroyInstance>(data.next(instance, "vkDestroyInstance"))(instance, allocator);
}

template <typename Function>
void resolve(Function& function, PFN_vkGetDeviceProcAddr next, VkDevice device, const char* name) {
    function = reinterpret_cast<Function>(next(device, name));
}

VKAPI_ATTR VkResult VKAPI_CALL createDevice(VkPhysicalDevice physical, const VkDeviceCreateInfo* createInfo,
                                            const VkAllocationCallbacks* allocator, VkDevice* device) {
    auto* link =
        findLinkInfo<VkLayerDeviceCreateInfo>(createInfo->pNext, VK_STRUCTURE_TYPE_LOADER_DEVICE_CREATE_INFO);
    if (link == nullptr) return VK_ERROR_INITIALIZATION_FAILED;
    PFN_vkGetInstanceProcAddr nextInstance = link->u.pLayerInfo->pfnNextGetInstanceProcAddr;
    PFN_vkGetDeviceProcAddr next = link->u.pLayerInfo->pfnNextGetDeviceProcAddr;
    link->u.pLayerInfo = link->u.pLayerInfo->pNext;
    VkInstance instance = instanceData(physical).handle;  // a physical device shares its instance's key
    auto create = reinterpret_cast<PFN_vkCreateDevice>(nextInstance(instance, "vkCreateDevice"));
    VkDeviceCreateInfo info = *createInfo;
    std::vector<const char*> extensions =
        withoutOurs(info.ppEnabledExtensionNames, info.enabledExtensionCount);
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result;
    {
        VkBaseOutStructure head{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                                .pNext = static_cast<VkBaseOutStructure*>(const_cast<void*>(info.pNext))};
        Unlinked feature;
        unlink(&head, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SWAPCHAIN_MAINTENANCE_1_FEATURES_EXT, feature);
        info.pNext = head.pNext;
        result = create(physical, &info, allocator, device);
        if (feature.previous == &head) feature.previous = nullptr;  // the head is ours: nothing to relink
    }
    if (result != VK_SUCCESS) return result;

    DeviceData data;
    data.getProcAddr = next;
    resolve(data.next.destroyDevice, next, *device, "vkDestroyDevice");
    resolve(data.next.allocateMemory, next, *device, "vkAllocateMemory");
    resolve(data.next.freeMemory, next, *device, "vkFreeMemory");
    resolve(data.next.createImage, next, *device, "vkCreateImage");
    resolve(data.next.createBuffer, next, *device, "vkCreateBuffer");
    resolve(data.next.createGraphicsPipelines, next, *device, "vkCreateGraphicsPipelines");
    resolve(data.next.createComputePipelines, next, *device, "vkCreateComputePipelines");
    resolve(data.next.queueSubmit, next, *device, "vkQueueSubmit");
    resolve(data.next.queueSubmit2, next, *device, "vkQueueSubmit2");
    resolve(data.next.waitForFences, next, *device, "vkWaitForFences");
    resolve(data.next.getFenceStatus, next, *device, "vkGetFenceStatus");
    resolve(data.next.deviceWaitIdle, next, *device, "vkDeviceWaitIdle");
    resolve(data.next.queueWaitIdle, next, *device, "vkQueueWaitIdle");
    resolve(data.next.getQueryPoolResults, next, *device, "vkGetQueryPoolResults");
    resolve(data.next.acquireNextImage, next, *device, "vkAcquireNextImageKHR");
    resolve(data.next.queuePresent, next, *device, "vkQueuePresentKHR");
    resolve(data.next.createSwapchain, next, *device, "vkCreateSwapchainKHR");
    resolve(data.next.destroySwapchain, next, *device, "vkDestroySwapchainKHR");
    std::lock_guard lock(gLock);
    gDevices[dispatchKey(*device)] = data;
    return VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL destroyDevice(VkDevice device, const VkAllocationCallbacks* allocator) {
    if (device == VK_NULL_HANDLE) return;
    PFN_vkDestroyDevice destroy = deviceData(device).next.destroyDevice;
    {
        std::lock_guard lock(gLock);
        gDevices.erase(dispatchKey(device));
    }
    destroy(device, allocator);
}

// ---- The intercepted calls ---------------------------------------------------------------------

// The calls that can run out of memory: the chosen one returns `failure` instead of reaching the
// driver; every other passes down.
#define FAIL_OR_PASS_DOWN(call, failure, function, device, ...) \
    DeviceData& data = deviceData(device);                      \
    {                                                           \
        std::lock_guard lock(gLock);                            \
        if (failsNow(call)) return failure;                     \
    }                                                           \
    return data.next.function(device, __VA_ARGS__)

VKAPI_ATTR VkResult VKAPI_CALL allocateMemory(VkDevice device, const VkMemoryAllocateInfo* info,
                                              const VkAllocationCallbacks* allocator,
                                              VkDeviceMemory* memory) {
    DeviceData& data = deviceData(device);
    {
        std::lock_guard lock(gLock);
        if (failsNow("vkAllocateMemory")) return VK_ERROR_OUT_OF_DEVICE_MEMORY;
        // A device that allows only so many allocations at a time (VKBOOK_MAX_ALLOCATIONS) fails
        // the one past them, as a driver does (VK_ERROR_TOO_MANY_OBJECTS).
        if (profile().maxAllocations != 0 && data.allocations >= profile().maxAllocations) {
            std::fprintf(stderr,
                         "VK_LAYER_VKBOOK_fault_injection: allocation %llu is past "
                         "VKBOOK_MAX_ALLOCATIONS\n",
                         (unsigned long long)data.allocations + 1);
            return VK_ERROR_TOO_MANY_OBJECTS;
        }
    }
    VkResult result = data.next.allocateMemory(device, info, allocator, memory);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(gLock);
        ++data.allocations;
    }
    return result;
}

VKAPI_ATTR void VKAPI_CALL freeMemory(VkDevice device, VkDeviceMemory memory,
                                      const VkAllocationCallbacks* allocator) {
    DeviceData& data = deviceData(device);
    if (memory != VK_NULL_HANDLE) {
        std::lock_guard lock(gLock);
        --data.allocations;
    }
    data.next.freeMemory(device, memory, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL createImage(VkDevice device, const VkImageCreateInfo* info,
                                           const VkAllocationCallbacks* allocator, VkImage* image) {
    FAIL_OR_PASS_DOWN("vkCreateImage", VK_ERROR_OUT_OF_HOST_MEMORY, createImage, device, info, allocator,
                      image);
}

VKAPI_ATTR VkResult VKAPI_CALL createBuffer(VkDevice device, const VkBufferCreateInfo* info,
                                            const VkAllocationCallbacks* allocator, VkBuffer* buffer) {
    FAIL_OR_PASS_DOWN("vkCreateBuffer", VK_ERROR_OUT_OF_HOST_MEMORY, createBuffer, device, info, allocator,
                      buffer);
}

// A pipeline the driver could not make: every handle VK_NULL_HANDLE, as the specification asks
// of a failed creation.
template <typename Info, typename Next>
VkResult createPipelines(const char* call, VkDevice device, VkPipelineCache cache, uint32_t count,
                         const Info* infos, const VkAllocationCallbacks* allocator, VkPipeline* pipelines,
                         Next next) {
    {
        std::lock_guard lock(gLock);
        if (failsNow(call)) {
            for (uint32_t i = 0; i < count; ++i) pipelines[i] = VK_NULL_HANDLE;
            return VK_ERROR_OUT_OF_DEVICE_MEMORY;
        }
    }
    return next(device, cache, count, infos, allocator, pipelines);
}

VKAPI_ATTR VkResult VKAPI_CALL createGraphicsPipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                       const VkGraphicsPipelineCreateInfo* infos,
                                                       const VkAllocationCallbacks* allocator,
                                                       VkPipeline* pipelines) {
    return createPipelines("vkCreateGraphicsPipelines", device, cache, count, infos, allocator, pipelines,
                           deviceData(device).next.createGraphicsPipelines);
}

VKAPI_ATTR VkResult VKAPI_CALL createComputePipelines(VkDevice device, VkPipelineCache cache, uint32_t count,
                                                      const VkComputePipelineCreateInfo* infos,
                                                      const VkAllocationCallbacks* allocator,
                                                      VkPipeline* pipelines) {
    return createPipelines("vkCreateComputePipelines", device, cache, count, infos, allocator, pipelines,
                           deviceData(device).next.createComputePipelines);
}

// The calls that report a device loss: each returns it instead of reaching the driver once the
// device is lost, and each can be the call that loses it.
#define LOSE_OR_PASS_DOWN(handle, call, function, ...)                           \
    DeviceData& data = deviceData(handle);                                       \
    if (VkResult lost = deviceLoss(data, call); lost != VK_SUCCESS) return lost; \
    return data.next.function(__VA_ARGS__)

// ---- When a swapchain may be destroyed (see the top of this file) --------------------------------
// Each takes gLock.

// A fence the application has seen signalled: the waits it completes release their swapchains.
void fenceSeen(DeviceData& data, VkFence fence) {
    std::erase_if(data.acquireWaits, [&](const AcquireWait& wait) {
        if (wait.fence != fence && !(wait.waited && wait.submitFence == fence)) return false;
        for (VkSwapchainKHR swapchain : wait.releases)
            if (auto found = data.swapchains.find(swapchain); found != data.swapchains.end())
                found->second.released = true;
        return true;
    });
    for (auto& [handle, state] : data.swapchains) std::erase(state.presentFences, fence);
}

// A device or queue wait returned: every submission made is done.
void idleSeen(DeviceData& data) {
    std::erase_if(data.acquireWaits, [&](const AcquireWait& wait) {
        if (!wait.waited) return false;
        for (VkSwapchainKHR swapchain : wait.releases)
            if (auto found = data.swapchains.find(swapchain); found != data.swapchains.end())
                found->second.released = true;
        return true;
    });
    data.idleSincePresent = true;
}

void semaphoreWaited(DeviceData& data, VkSemaphore semaphore, VkFence fence) {
    for (AcquireWait& wait : data.acquireWaits)
        if (!wait.waited && wait.semaphore == semaphore) {
            wait.waited = true;
            wait.submitFence = fence;
        }
}

VKAPI_ATTR VkResult VKAPI_CALL queueSubmit(VkQueue queue, uint32_t count, const VkSubmitInfo* submits,
                                           VkFence fence) {
    DeviceData& data = deviceData(queue);
    if (VkResult lost = deviceLoss(data, "vkQueueSubmit"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.queueSubmit(queue, count, submits, fence);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(gLock);
        for (uint32_t i = 0; i < count; ++i)
            for (uint32_t w = 0; w < submits[i].waitSemaphoreCount; ++w)
                semaphoreWaited(data, submits[i].pWaitSemaphores[w], fence);
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL queueSubmit2(VkQueue queue, uint32_t count, const VkSubmitInfo2* submits,
                                            VkFence fence) {
    DeviceData& data = deviceData(queue);
    if (VkResult lost = deviceLoss(data, "vkQueueSubmit2"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.queueSubmit2(queue, count, submits, fence);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(gLock);
        for (uint32_t i = 0; i < count; ++i)
            for (uint32_t w = 0; w < submits[i].waitSemaphoreInfoCount; ++w)
                semaphoreWaited(data, submits[i].pWaitSemaphoreInfos[w].semaphore, fence);
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL waitForFences(VkDevice device, uint32_t count, const VkFence* fences,
                                             VkBool32 waitAll, uint64_t timeout) {
    DeviceData& data = deviceData(device);
    if (VkResult lost = deviceLoss(data, "vkWaitForFences"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.waitForFences(device, count, fences, waitAll, timeout);
    if (result == VK_SUCCESS)
        for (uint32_t i = 0; i < count; ++i)
            if (waitAll || count == 1 || data.next.getFenceStatus(device, fences[i]) == VK_SUCCESS) {
                std::lock_guard lock(gLock);
                fenceSeen(data, fences[i]);
            }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL getFenceStatus(VkDevice device, VkFence fence) {
    DeviceData& data = deviceData(device);
    if (VkResult lost = deviceLoss(data, "vkGetFenceStatus"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.getFenceStatus(device, fence);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(gLock);
        fenceSeen(data, fence);
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL deviceWaitIdle(VkDevice device) {
    DeviceData& data = deviceData(device);
    if (VkResult lost = deviceLoss(data, "vkDeviceWaitIdle"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.deviceWaitIdle(device);
    if (result == VK_SUCCESS) {
        std::lock_guard lock(gLock);
        idleSeen(data);
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL queueWaitIdle(VkQueue queue) {
    DeviceData& data = deviceData(queue);
    if (VkResult lost = deviceLoss(data, "vkQueueWaitIdle"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.queueWaitIdle(queue);
    if (result == VK_SUCCESS) {  // one queue per device in these programs
        std::lock_guard lock(gLock);
        idleSeen(data);
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL getQueryPoolResults(VkDevice device, VkQueryPool pool, uint32_t first,
                                                   uint32_t count, size_t size, void* results,
                                                   VkDeviceSize stride, VkQueryResultFlags flags) {
    LOSE_OR_PASS_DOWN(device, "vkGetQueryPoolResults", getQueryPoolResults, device, pool, first, count, size,
                      results, stride, flags);
}

VKAPI_ATTR VkResult VKAPI_CALL createSwapchain(VkDevice device, const VkSwapchainCreateInfoKHR* info,
                                               const VkAllocationCallbacks* allocator,
                                               VkSwapchainKHR* swapchain) {
    DeviceData& data = deviceData(device);
    VkResult result = data.next.createSwapchain(device, info, allocator, swapchain);
    if (result != VK_SUCCESS) return result;
    std::lock_guard lock(gLock);
    gSwapchainMade = true;
    if (auto old = data.swapchains.find(info->oldSwapchain); old != data.swapchains.end())
        old->second.retired = true;
    SwapchainState state;
    for (auto& [handle, other] : data.swapchains)
        if (other.retired && !other.released) state.olderRetired.push_back(handle);
    data.swapchains[*swapchain] = std::move(state);
    return result;
}

VKAPI_ATTR void VKAPI_CALL destroySwapchain(VkDevice device, VkSwapchainKHR swapchain,
                                            const VkAllocationCallbacks* allocator) {
    DeviceData& data = deviceData(device);
    if (swapchain != VK_NULL_HANDLE) {
        std::lock_guard lock(gLock);
        auto found = data.swapchains.find(swapchain);
        if (found != data.swapchains.end() && !data.lost) {
            const SwapchainState& state = found->second;
            // Every presentation carried a fence (VK_EXT_swapchain_maintenance1), each seen
            // signalled; also true of a swapchain never presented.
            bool presentFencesSeen = state.presentsWithoutFence == 0 && state.presentFences.empty();
            // A device wait says nothing of the presentation engine, but with nothing presented
            // since, at the end of a run (no swapchain left in use), nothing better can be known
            // without present fences: the current swapchain then, and the retired ones after it.
            bool current = false;
            for (const auto& [handle, other] : data.swapchains) current = current || !other.retired;
            bool endOfRun = data.idleSincePresent && (!state.retired || !current);
            if (!(presentFencesSeen || state.released || endOfRun))
                std::fprintf(
                    stderr,
                    "VK_LAYER_VKBOOK_fault_injection: vkDestroySwapchainKHR: %s swapchain destroyed "
                    "while the presentation engine may still use its images (%s)\n",
                    state.retired ? "a retired" : "the current",
                    state.retired
                        ? "no wait on an acquire of an image presented after its retirement "
                          "was seen complete"
                        : "presented since the last device wait, and not every presentation's fence seen "
                          "signalled");
        }
        if (found != data.swapchains.end()) data.swapchains.erase(found);
    }
    data.next.destroySwapchain(device, swapchain, allocator);
}

VKAPI_ATTR VkResult VKAPI_CALL acquireNextImage(VkDevice device, VkSwapchainKHR swapchain, uint64_t timeout,
                                                VkSemaphore semaphore, VkFence fence, uint32_t* index) {
    DeviceData& data = deviceData(device);
    if (VkResult lost = deviceLoss(data, "vkAcquireNextImageKHR"); lost != VK_SUCCESS) return lost;
    VkResult result = data.next.acquireNextImage(device, swapchain, timeout, semaphore, fence, index);
    if (result == VK_SUCCESS || result == VK_SUBOPTIMAL_KHR) {
        std::lock_guard lock(gLock);
        auto found = data.swapchains.find(swapchain);
        if (found != data.swapchains.end() && *index < found->second.presented.size() &&
            found->second.presented[*index] && !found->second.olderRetired.empty())
            data.acquireWaits.push_back(
                {fence, semaphore, false, VK_NULL_HANDLE, found->second.olderRetired});
    }
    return result;
}

VKAPI_ATTR VkResult VKAPI_CALL queuePresent(VkQueue queue, const VkPresentInfoKHR* info) {
    DeviceData& data = deviceData(queue);
    if (VkResult lost = deviceLoss(data, "vkQueuePresentKHR"); lost != VK_SUCCESS) return lost;
    // VK_EXT_swapchain_maintenance1's present fences, emulated: taken out of the chain, then
    // signalled by an empty submission after the presentation.
    VkPresentInfoKHR present = *info;
    VkBaseOutStructure head{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                            .pNext = static_cast<VkBaseOutStructure*>(const_cast<void*>(present.pNext))};
    Unlinked fences;
    unlink(&head, VK_STRUCTURE_TYPE_SWAPCHAIN_PRESENT_FENCE_INFO_EXT, fences);
    present.pNext = head.pNext;
    if (fences.previous == &head) fences.previous = nullptr;
    VkResult result = data.next.queuePresent(queue, &present);
    const auto* fenceInfo = reinterpret_cast<const VkSwapchainPresentFenceInfoEXT*>(fences.found);
    {
        std::lock_guard lock(gLock);
        data.idleSincePresent = false;
        for (uint32_t i = 0; i < info->swapchainCount; ++i) {
            auto found = data.swapchains.find(info->pSwapchains[i]);
            if (found == data.swapchains.end()) continue;
            std::vector<bool>& presented = found->second.presented;
            if (presented.size() <= info->pImageIndices[i]) presented.resize(info->pImageIndices[i] + 1);
            presented[info->pImageIndices[i]] = true;
            if (fenceInfo && fenceInfo->pFences[i] != VK_NULL_HANDLE)
                found->second.presentFences.push_back(fenceInfo->pFences[i]);
            else
                ++found->second.presentsWithoutFence;
        }
    }
    if (fenceInfo &&
        (result == VK_SUCCESS || result == VK_SUBOPTIMAL_KHR || result == VK_ERROR_OUT_OF_DATE_KHR)) {
        for (uint32_t i = 0; i < fenceInfo->swapchainCount; ++i)
            if (fenceInfo->pFences[i] != VK_NULL_HANDLE)
                if (VkResult signalled = data.next.queueSubmit(queue, 0, nullptr, fenceInfo->pFences[i]);
                    signalled != VK_SUCCESS)
                    return signalled;
    }
    return result;
}

#undef LOSE_OR_PASS_DOWN
#undef FAIL_OR_PASS_DOWN

// ---- Physical-device queries, answered as the profile says --------------------------------------

template <typename Function>
Function nextInstanceCall(VkPhysicalDevice physical, const char* name) {
    const InstanceData& data = instanceData(physical);
    auto found = data.calls.find(name);
    PFN_vkVoidFunction call = found != data.calls.end() ? found->second : nullptr;
    if (call == nullptr)  // a Vulkan 1.0 instance: the extension's form
        if (auto khr = data.calls.find(std::string(name) + "KHR"); khr != data.calls.end())
            call = khr->second;
    if (call ==
        nullptr) {  // kInstanceCalls lacks the name, or getInstanceProcAddr gave out a wrapper it should not
        std::fprintf(stderr, "VK_LAYER_VKBOOK_fault_injection: no next %s\n", name);
        std::abort();
    }
    return reinterpret_cast<Function>(call);
}

void lowerVersion(VkPhysicalDeviceProperties& properties) {
    if (profile().apiVersion != 0 && profile().apiVersion < properties.apiVersion)
        properties.apiVersion = profile().apiVersion;
    if (profile().maxAllocations != 0 &&
        profile().maxAllocations < properties.limits.maxMemoryAllocationCount)
        properties.limits.maxMemoryAllocationCount = profile().maxAllocations;
    if (profile().maxComputeGroups != 0 &&
        profile().maxComputeGroups < properties.limits.maxComputeWorkGroupCount[0])
        properties.limits.maxComputeWorkGroupCount[0] = profile().maxComputeGroups;
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceProperties(VkPhysicalDevice physical,
                                                       VkPhysicalDeviceProperties* properties) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceProperties>(physical, "vkGetPhysicalDeviceProperties")(
        physical, properties);
    lowerVersion(*properties);
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceProperties2(VkPhysicalDevice physical,
                                                        VkPhysicalDeviceProperties2* properties) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceProperties2>(physical, "vkGetPhysicalDeviceProperties2")(
        physical, properties);
    lowerVersion(properties->properties);
}

void shrinkHeaps(VkPhysicalDeviceMemoryProperties& memory) {
    const VkDeviceSize limit = VkDeviceSize(profile().heapMib) << 20;
    for (uint32_t i = 0; i < memory.memoryHeapCount && limit != 0; ++i)
        if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            memory.memoryHeaps[i].size = std::min(memory.memoryHeaps[i].size, limit);
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceMemoryProperties(VkPhysicalDevice physical,
                                                             VkPhysicalDeviceMemoryProperties* memory) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceMemoryProperties>(
        physical, "vkGetPhysicalDeviceMemoryProperties")(physical, memory);
    shrinkHeaps(*memory);
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceMemoryProperties2(VkPhysicalDevice physical,
                                                              VkPhysicalDeviceMemoryProperties2* memory) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceMemoryProperties2>(
        physical, "vkGetPhysicalDeviceMemoryProperties2")(physical, memory);
    shrinkHeaps(memory->memoryProperties);
}

// The core features VKBOOK_HIDE names, cleared.
void hideCoreFeatures(VkPhysicalDeviceFeatures& features) {
    if (hidden("geometryShader")) features.geometryShader = VK_FALSE;
    if (hidden("depthClamp")) features.depthClamp = VK_FALSE;
    if (hidden("shaderInt64")) features.shaderInt64 = VK_FALSE;
    if (hidden("multiDrawIndirect")) features.multiDrawIndirect = VK_FALSE;
    if (hidden("drawIndirectFirstInstance")) features.drawIndirectFirstInstance = VK_FALSE;
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFeatures(VkPhysicalDevice physical,
                                                     VkPhysicalDeviceFeatures* features) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceFeatures>(physical, "vkGetPhysicalDeviceFeatures")(physical,
                                                                                               features);
    hideCoreFeatures(*features);
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFeatures2(VkPhysicalDevice physical,
                                                      VkPhysicalDeviceFeatures2* features) {
    VkBaseOutStructure head{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                            .pNext = reinterpret_cast<VkBaseOutStructure*>(features)};
    Unlinked maintenance1;
    unlink(&head, VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SWAPCHAIN_MAINTENANCE_1_FEATURES_EXT, maintenance1);
    nextInstanceCall<PFN_vkGetPhysicalDeviceFeatures2>(physical, "vkGetPhysicalDeviceFeatures2")(physical,
                                                                                                 features);
    if (maintenance1.found)
        reinterpret_cast<VkPhysicalDeviceSwapchainMaintenance1FeaturesEXT*>(maintenance1.found)
            ->swapchainMaintenance1 = profile().maintenance1 ? VK_TRUE : VK_FALSE;
    hideCoreFeatures(features->features);
    if (hidden("bufferDeviceAddress"))
        for (auto* s = reinterpret_cast<VkBaseOutStructure*>(features); s; s = s->pNext) {
            if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES)
                reinterpret_cast<VkPhysicalDeviceVulkan12Features*>(s)->bufferDeviceAddress = VK_FALSE;
            if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES)
                reinterpret_cast<VkPhysicalDeviceBufferDeviceAddressFeatures*>(s)->bufferDeviceAddress =
                    VK_FALSE;
        }
    if (hidden("scalarBlockLayout"))
        for (auto* s = reinterpret_cast<VkBaseOutStructure*>(features); s; s = s->pNext) {
            if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES)
                reinterpret_cast<VkPhysicalDeviceVulkan12Features*>(s)->scalarBlockLayout = VK_FALSE;
            if (s->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SCALAR_BLOCK_LAYOUT_FEATURES)
                reinterpret_cast<VkPhysicalDeviceScalarBlockLayoutFeatures*>(s)->scalarBlockLayout = VK_FALSE;
        }
}

VKAPI_ATTR VkResult VKAPI_CALL enumerateDeviceExtensionProperties(VkPhysicalDevice physical,
                                                                  const char* layerName, uint32_t* count,
                                                                  VkExtensionProperties* properties) {
    auto next = nextInstanceCall<PFN_vkEnumerateDeviceExtensionProperties>(
        physical, "vkEnumerateDeviceExtensionProperties");
    if (layerName != nullptr) return next(physical, layerName, count, properties);
    uint32_t all = 0;
    VkResult result = next(physical, nullptr, &all, nullptr);
    if (result != VK_SUCCESS) return result;
    std::vector<VkExtensionProperties> extensions(all);
    result = next(physical, nullptr, &all, extensions.data());
    if (result != VK_SUCCESS) return result;
    std::erase_if(extensions, [](const VkExtensionProperties& e) { return hidden(e.extensionName); });
    if (profile().maintenance1) {
        VkExtensionProperties maintenance1{VK_EXT_SWAPCHAIN_MAINTENANCE_1_EXTENSION_NAME, 1};
        extensions.push_back(maintenance1);
    }
    if (properties == nullptr) {
        *count = uint32_t(extensions.size());
        return VK_SUCCESS;
    }
    uint32_t written = std::min(*count, uint32_t(extensions.size()));
    std::copy_n(extensions.begin(), written, properties);
    *count = written;
    return written < extensions.size() ? VK_INCOMPLETE : VK_SUCCESS;
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFormatProperties(VkPhysicalDevice physical, VkFormat format,
                                                             VkFormatProperties* properties) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceFormatProperties>(
        physical, "vkGetPhysicalDeviceFormatProperties")(physical, format, properties);
    if (hidden(format)) *properties = {};
}

VKAPI_ATTR void VKAPI_CALL getPhysicalDeviceFormatProperties2(VkPhysicalDevice physical, VkFormat format,
                                                              VkFormatProperties2* properties) {
    nextInstanceCall<PFN_vkGetPhysicalDeviceFormatProperties2>(
        physical, "vkGetPhysicalDeviceFormatProperties2")(physical, format, properties);
    if (hidden(format)) properties->formatProperties = {};
}

VKAPI_ATTR VkResult VKAPI_CALL getPhysicalDeviceSurfaceFormats(VkPhysicalDevice physical,
                                                               VkSurfaceKHR surface, uint32_t* count,
                                                               VkSurfaceFormatKHR* formats) {
    auto next = nextInstanceCall<PFN_vkGetPhysicalDeviceSurfaceFormatsKHR>(
        physical, "vkGetPhysicalDeviceSurfaceFormatsKHR");
    uint32_t all = 0;
    VkResult result = next(physical, surface, &all, nullptr);
    if (result != VK_SUCCESS) return result;
    std::vector<VkSurfaceFormatKHR> offered(all);
    result = next(physical, surface, &all, offered.data());
    if (result != VK_SUCCESS && result != VK_INCOMPLETE) return result;
    offered.resize(all);
    bool later;
    {
        std::lock_guard lock(gLock);
        later = gSwapchainMade;
    }
    std::erase_if(offered, [&](const VkSurfaceFormatKHR& f) {
        return hidden(f.format) || (later && named(profile().hiddenLater, f.format));
    });
    if (formats == nullptr) {
        *count = uint32_t(offered.size());
        return VK_SUCCESS;
    }
    uint32_t written = std::min(*count, uint32_t(offered.size()));
    std::copy_n(offered.begin(), written, formats);
    *count = written;
    return written < offered.size() ? VK_INCOMPLETE : VK_SUCCESS;
}

// ---- GetProcAddr: our functions for the calls we intercept, the next layer's for the rest ------

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name);

PFN_vkVoidFunction interceptedDeviceCall(const char* name) {
    static const std::unordered_map<std::string, PFN_vkVoidFunction> calls = {
        {"vkGetDeviceProcAddr", reinterpret_cast<PFN_vkVoidFunction>(getDeviceProcAddr)},
        {"vkDestroyDevice", reinterpret_cast<PFN_vkVoidFunction>(destroyDevice)},
        {"vkAllocateMemory", reinterpret_cast<PFN_vkVoidFunction>(allocateMemory)},
        {"vkFreeMemory", reinterpret_cast<PFN_vkVoidFunction>(freeMemory)},
        {"vkCreateImage", reinterpret_cast<PFN_vkVoidFunction>(createImage)},
        {"vkCreateBuffer", reinterpret_cast<PFN_vkVoidFunction>(createBuffer)},
        {"vkCreateGraphicsPipelines", reinterpret_cast<PFN_vkVoidFunction>(createGraphicsPipelines)},
        {"vkCreateComputePipelines", reinterpret_cast<PFN_vkVoidFunction>(createComputePipelines)},
        {"vkQueueSubmit", reinterpret_cast<PFN_vkVoidFunction>(queueSubmit)},
        {"vkQueueSubmit2", reinterpret_cast<PFN_vkVoidFunction>(queueSubmit2)},
        {"vkQueueSubmit2KHR", reinterpret_cast<PFN_vkVoidFunction>(queueSubmit2)},
        {"vkWaitForFences", reinterpret_cast<PFN_vkVoidFunction>(waitForFences)},
        {"vkGetFenceStatus", reinterpret_cast<PFN_vkVoidFunction>(getFenceStatus)},
        {"vkDeviceWaitIdle", reinterpret_cast<PFN_vkVoidFunction>(deviceWaitIdle)},
        {"vkQueueWaitIdle", reinterpret_cast<PFN_vkVoidFunction>(queueWaitIdle)},
        {"vkGetQueryPoolResults", reinterpret_cast<PFN_vkVoidFunction>(getQueryPoolResults)},
        {"vkAcquireNextImageKHR", reinterpret_cast<PFN_vkVoidFunction>(acquireNextImage)},
        {"vkQueuePresentKHR", reinterpret_cast<PFN_vkVoidFunction>(queuePresent)},
        {"vkCreateSwapchainKHR", reinterpret_cast<PFN_vkVoidFunction>(createSwapchain)},
        {"vkDestroySwapchainKHR", reinterpret_cast<PFN_vkVoidFunction>(destroySwapchain)},
    };
    auto found = calls.find(name);
    return found == calls.end() ? nullptr : found->second;
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice device, const char* name) {
    PFN_vkGetDeviceProcAddr next = deviceData(device).getProcAddr;
    // Only what the device has: no vkAcquireNextImageKHR of ours on a device without swapchains.
    if (PFN_vkVoidFunction ours = interceptedDeviceCall(name); ours && next(device, name)) return ours;
    return next(device, name);
}

VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getInstanceProcAddr(VkInstance instance, const char* name) {
    if (std::strcmp(name, "vkGetInstanceProcAddr") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(getInstanceProcAddr);
    if (std::strcmp(name, "vkCreateInstance") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(createInstance);
    if (std::strcmp(name, "vkDestroyInstance") == 0)
        return reinterpret_cast<PFN_vkVoidFunction>(destroyInstance);
    if (std::strcmp(name, "vkCreateDevice") == 0) return reinterpret_cast<PFN_vkVoidFunction>(createDevice);
    static const std::unordered_map<std::string, PFN_vkVoidFunction> physicalDeviceCalls = {
        {"vkGetPhysicalDeviceProperties", reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceProperties)},
        {"vkGetPhysicalDeviceProperties2",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceProperties2)},
        {"vkGetPhysicalDeviceProperties2KHR",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceProperties2)},
        {"vkEnumerateDeviceExtensionProperties",
         reinterpret_cast<PFN_vkVoidFunction>(enumerateDeviceExtensionProperties)},
        {"vkGetPhysicalDeviceFormatProperties",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFormatProperties)},
        {"vkGetPhysicalDeviceFormatProperties2",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFormatProperties2)},
        {"vkGetPhysicalDeviceFormatProperties2KHR",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFormatProperties2)},
        {"vkGetPhysicalDeviceSurfaceFormatsKHR",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceSurfaceFormats)},
        {"vkGetPhysicalDeviceFeatures", reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFeatures)},
        {"vkGetPhysicalDeviceFeatures2", reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFeatures2)},
        {"vkGetPhysicalDeviceMemoryProperties",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceMemoryProperties)},
        {"vkGetPhysicalDeviceMemoryProperties2",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceMemoryProperties2)},
        {"vkGetPhysicalDeviceMemoryProperties2KHR",
         reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceMemoryProperties2)},
        {"vkGetPhysicalDeviceFeatures2KHR", reinterpret_cast<PFN_vkVoidFunction>(getPhysicalDeviceFeatures2)},
    };
    // Ours only where the layers below have the call (a Vulkan 1.0 instance may lack the "2"
    // queries): an application's null check then stays true to the device.
    if (auto found = physicalDeviceCalls.find(name); found != physicalDeviceCalls.end()) {
        if (instance == VK_NULL_HANDLE) return nullptr;
        const InstanceData& data = instanceData(instance);
        auto next = data.calls.find(name);
        return next != data.calls.end() && next->second != nullptr ? found->second : nullptr;
    }
    if (PFN_vkVoidFunction ours = interceptedDeviceCall(name)) return ours;
    if (instance == VK_NULL_HANDLE) return nullptr;
    return instanceData(instance).next(instance, name);
}

}  // namespace

VKBOOK_LAYER_ENTRY_POINTS(getInstanceProcAddr, getDeviceProcAddr)
