// Test helper: runs one compute shader over buffers and waits for it. Used by the tests that
// check GPU code on the GPU (the layout test, the numeric tests of the shading math).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/vk/device.hpp"

struct ComputeBinding {
    VkDescriptorType type;  // STORAGE_BUFFER or UNIFORM_BUFFER
    VkBuffer buffer;
};

// Binds `bindings` as set 0 (binding i = bindings[i]), pushes `pushSize` bytes of `push`,
// dispatches `groups` workgroups, makes the results visible to the host and waits.
void runCompute(const common::Device& device, const std::filesystem::path& spirv,
                const std::vector<ComputeBinding>& bindings, const void* push, uint32_t pushSize,
                uint32_t groups);
