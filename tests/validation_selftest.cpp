// validation_selftest: proves that --validation can fail. It creates an instance and device the
// way every chapter does (common::createInstance with validation on), then makes two deliberate
// mistakes and checks that each one is counted:
//   1. an API misuse (a buffer of size 0) -- core validation;
//   2. two copies writing the same buffer with no barrier between them -- a WRITE_AFTER_WRITE
//      hazard that only synchronization validation reports.
// Exit 0 when both were reported, 1 otherwise.
#include <cstdio>

#include "common/buffer.hpp"
#include "common/check.hpp"
#include "common/commands.hpp"
#include "common/device.hpp"
#include "common/instance.hpp"

int main() {
    try {
        common::Instance instance = common::createInstance("validation_selftest", true, {});
        common::Device device = common::createDevice(instance, VK_NULL_HANDLE, "");

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
                                                     VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT);
        common::Buffer target = common::createBuffer(device, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                     VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VkCommandBuffer cmd = common::beginOneTimeCommands(device);
        VkBufferCopy region{0, 0, 256};
        vkCmdCopyBuffer(cmd, source.handle, target.handle, 1, &region);
        vkCmdCopyBuffer(cmd, source.handle, target.handle, 1, &region);  // no barrier: a hazard
        common::submitOneTimeCommands(device, cmd);
        bool syncReported = common::validationMessageCount() > before;

        common::destroyBuffer(device, target);
        common::destroyBuffer(device, source);
        common::destroyDevice(device);
        common::destroyInstance(instance);

        std::printf("core validation reported the misuse: %s\n", coreReported ? "yes" : "NO");
        std::printf("synchronization validation reported the hazard: %s\n", syncReported ? "yes" : "NO");
        return coreReported && syncReported ? 0 : 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "validation_selftest: %s\n", error.what());
        return 1;
    }
}
