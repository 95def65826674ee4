// The camera's uniform buffers and descriptor sets, one per frame in flight.
#include "common/passes/camera_frames.hpp"

#include <cstring>
#include <string>

#include "common/vk/descriptors.hpp"

namespace common {

VkDescriptorSetLayout createCameraSetLayout(const Device& device) {
    return createDescriptorSetLayout(
        device, {binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)}, "camera");
}

std::vector<CameraFrame> createCameraFrames(const Device& device, VkDescriptorPool pool,
                                            VkDescriptorSetLayout layout, uint32_t framesInFlight) {
    std::vector<CameraFrame> frames(framesInFlight);
    for (size_t i = 0; i < frames.size(); ++i) {
        CameraFrame& frame = frames[i];
        frame.buffer =
            createBuffer(device, sizeof(CameraUniform), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                         "camera, frame " + std::to_string(i));
        frame.set = allocateDescriptorSet(device, pool, layout, "camera, frame " + std::to_string(i));
        writeBufferDescriptor(device, frame.set, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame.buffer.handle,
                              sizeof(CameraUniform));
    }
    return frames;
}

void writeCamera(CameraFrame& frame, const glm::mat4& projection, const glm::mat4& view) {
    CameraUniform camera{projection, view};
    std::memcpy(frame.buffer.mapped, &camera, sizeof(camera));
}

void destroyCameraFrames(const Device& device, std::vector<CameraFrame>& frames) {
    for (CameraFrame& frame : frames) destroyBuffer(device, frame.buffer);  // the sets go with their pool
    frames.clear();
}

}  // namespace common
