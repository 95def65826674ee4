// The camera's matrices on the GPU: a uniform buffer and its descriptor set per frame in
// flight, which the scene passes of chapters 14 on bind at set 0 (the book's chapter 9 keeps its
// projection and view matrices in uniform buffers so). The matrices themselves come from
// common/scene/camera.hpp.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"

namespace common {

// The camera as the scene passes of chapters 14 and 15 read it: set 0, binding 0, the twin of
// `uniform CameraUniform` in shaders/chapter-14/scene.vert and shaders/chapter-15/scene.vert
// (std140: two column-major mat4, 128 bytes; tests/chapters/layout_test.cpp checks it on the GPU).
struct CameraUniform {
    glm::mat4 projection;
    glm::mat4 view;
};
static_assert(sizeof(CameraUniform) == 128);

// One per frame in flight: the camera's host-visible uniform buffer, written every frame, and
// the descriptor set that binds it.
struct CameraFrame {
    Buffer buffer;
    VkDescriptorSet set = VK_NULL_HANDLE;
};

// The set layout: binding 0, a uniform buffer read by the vertex stage.
VkDescriptorSetLayout createCameraSetLayout(const Device& device);
// `pool` must have room for `framesInFlight` sets of one uniform buffer each.
std::vector<CameraFrame> createCameraFrames(const Device& device, VkDescriptorPool pool,
                                            VkDescriptorSetLayout layout, uint32_t framesInFlight);
void writeCamera(CameraFrame& frame, const glm::mat4& projection, const glm::mat4& view);
void destroyCameraFrames(const Device& device, std::vector<CameraFrame>& frames);

}  // namespace common
