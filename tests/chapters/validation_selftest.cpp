// validation_selftest: proves that --validation can fail, through the same runChapter() every
// chapter's main() uses. With --validation it creates an instance and a device as the chapters
// do, then makes three deliberate mistakes and checks that each one is counted:
//   1. an API misuse (a buffer of size 0) -- core validation;
//   2. two copies writing the same buffer with no barrier between them -- a WRITE_AFTER_WRITE
//      hazard that only synchronization validation reports;
//   3. a sampler left alive when the device is destroyed -- object tracking, the check that makes
//      every chapter test's silent exit mean "every Vulkan object was destroyed in time".
// Expected: exit code 3 (validation messages), as a chapter would end. Exit 1 means a mistake
// went unreported.
#include <cstdio>

#include "common/app/cli.hpp"
#include "common/core/check.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"

namespace {

void makeMistakes(const common::Options& options) {
    common::Instance instance = common::createInstance("validation_selftest", options.validation, {});
    common::Device device = common::createDevice(instance, VK_NULL_HANDLE, options.device);

    std::fprintf(stderr, "--- expected: a core validation error (buffer size 0) ---\n");
    uint32_t before = common::validationMessageCount();
    VkBufferCreateInfo zero{
        .sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
        .size = 0,
        .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
    };
    VkBuffer bad = VK_NULL_HANDLE;
    if (vkCreateBuffer(device.handle, &zero, nullptr, &bad) == VK_SUCCESS && bad != VK_NULL_HANDLE)
        vkDestroyBuffer(device.handle, bad, nullptr);
    bool coreReported = common::validationMessageCount() > before;

    std::fprintf(stderr, "--- expected: a synchronization hazard (WRITE_AFTER_WRITE) ---\n");
    before = common::validationMessageCount();
    common::Buffer source = common::createBuffer(device, 256, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                                 VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, "source");
    common::Buffer target = common::createBuffer(device, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                 VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "target");
    VkCommandBuffer cmd = common::beginOneTimeCommands(device);
    VkBufferCopy region{0, 0, 256};
    vkCmdCopyBuffer(cmd, source.handle, target.handle, 1, &region);
    vkCmdCopyBuffer(cmd, source.handle, target.handle, 1, &region);  // no barrier: a hazard
    common::submitOneTimeCommands(device, cmd);
    bool syncReported = common::validationMessageCount() > before;

    common::destroyBuffer(device, target);
    common::destroyBuffer(device, source);

    std::fprintf(stderr, "--- expected: an object not destroyed before its device ---\n");
    VkSamplerCreateInfo samplerInfo{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler leaked = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(device.handle, &samplerInfo, nullptr, &leaked));
    before = common::validationMessageCount();
    common::destroyDevice(device);  // the sampler is still alive
    bool leakReported = common::validationMessageCount() > before;
    common::destroyInstance(instance);

    std::printf("core validation reported the misuse: %s\n", coreReported ? "yes" : "NO");
    std::printf("synchronization validation reported the hazard: %s\n", syncReported ? "yes" : "NO");
    std::printf("object tracking reported the leaked sampler: %s\n", leakReported ? "yes" : "NO");
    if (!coreReported || !syncReported || !leakReported)
        throw common::Failure("a deliberate mistake was not reported");
}

}  // namespace

int main(int argc, char** argv) {
    return common::runChapter(argc, argv, {"validation_selftest", "makes three deliberate mistakes", {}},
                              makeMistakes);
}
