// bandwidth [--device NAME] [--mib N] [--repeats N] [--json FILE]: the device's memory bandwidth as
// seen by a buffer-to-buffer copy (vkCmdCopyBuffer between two device-local buffers), timed with
// timestamp queries. A copy reads and writes every byte, so bandwidth = 2 * size / time; the
// median over the repeats is reported. docs/performance.md divides a G-buffer's bytes by it.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/core/check.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/device.hpp"
#include "common/vk/instance.hpp"

int main(int argc, char** argv) {
    std::string deviceName, jsonPath;
    unsigned long mib = 256, repeats = 10;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (i + 1 >= argc) {
            std::fprintf(stderr, "bandwidth: %s needs a value\n", arg.c_str());
            return 2;
        }
        std::string value = argv[++i];
        char* end = nullptr;
        if (arg == "--device")
            deviceName = value;
        else if (arg == "--json")
            jsonPath = value;
        else if (arg == "--mib" || arg == "--repeats") {
            unsigned long n = std::strtoul(value.c_str(), &end, 10);
            if (*end != '\0' || n < 1 || n > 16384) {
                std::fprintf(stderr, "bandwidth: %s takes a number 1..16384, not '%s'\n", arg.c_str(),
                             value.c_str());
                return 2;
            }
            (arg == "--mib" ? mib : repeats) = n;
        } else {
            std::fprintf(stderr, "bandwidth: unknown option %s\n", arg.c_str());
            return 2;
        }
    }

    try {
        common::Instance instance = common::createInstance("bandwidth", false, {});
        common::Device device = common::createDevice(instance, VK_NULL_HANDLE, deviceName);
        if (device.timestampValidBits == 0) {
            std::fprintf(stderr, "bandwidth: %s has no timestamps on its graphics queue\n",
                         device.properties.deviceName);
            return 1;
        }
        VkDeviceSize size = VkDeviceSize(mib) << 20;
        VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        common::Buffer source = common::createBuffer(device, size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                                     "bandwidth source");
        common::Buffer target = common::createBuffer(device, size, usage, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                                     "bandwidth destination");

        VkQueryPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                       .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                       .queryCount = 2};
        VkQueryPool pool;
        VK_CHECK(vkCreateQueryPool(device.handle, &poolInfo, nullptr, &pool));

        // One warm-up copy (first touch of the memory), then the timed ones, each its own submit.
        std::vector<double> ms;
        for (unsigned long r = 0; r <= repeats; ++r) {
            VkCommandBuffer cmd = common::beginOneTimeCommands(device);
            vkCmdResetQueryPool(cmd, pool, 0, 2);
            vkCmdFillBuffer(cmd, source.handle, 0, VK_WHOLE_SIZE, uint32_t(r));
            VkMemoryBarrier fillDone{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER,
                                     .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                                     .dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT};
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                                 &fillDone, 0, nullptr, 0, nullptr);
            vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, pool, 0);
            VkBufferCopy region{.size = size};
            vkCmdCopyBuffer(cmd, source.handle, target.handle, 1, &region);
            vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, pool, 1);
            common::submitOneTimeCommands(device, cmd);
            uint64_t stamps[2];
            VK_CHECK(vkGetQueryPoolResults(device.handle, pool, 0, 2, sizeof(stamps), stamps,
                                           sizeof(uint64_t),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
            if (r > 0)
                ms.push_back(double(stamps[1] - stamps[0]) * device.properties.limits.timestampPeriod * 1e-6);
        }
        std::sort(ms.begin(), ms.end());
        double median = ms[ms.size() / 2];
        double gbPerSecond = 2.0 * double(size) / (median * 1e-3) / 1e9;
        std::printf(
            "device     %s\ndriver     %s\ncopy       %lu MiB, median of %lu: %.3f ms\n"
            "bandwidth  %.1f GB/s (read + write)\n",
            device.properties.deviceName, device.driver.c_str(), mib, repeats, median, gbPerSecond);
        if (!jsonPath.empty()) {
            nlohmann::json report = {{"device", device.properties.deviceName},
                                     {"driver", device.driver},
                                     {"copy_mib", mib},
                                     {"copy_ms", median},
                                     {"bandwidth_gb_per_s", gbPerSecond}};
            std::ofstream out(jsonPath);
            out << report.dump(2) << "\n";
            if (!out) throw std::runtime_error("cannot write " + jsonPath);
        }
        vkDestroyQueryPool(device.handle, pool, nullptr);
        common::destroyBuffer(device, source);
        common::destroyBuffer(device, target);
        common::destroyDevice(device);
        common::destroyInstance(instance);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "bandwidth: %s\n", error.what());
        return 1;
    }
    return 0;
}
