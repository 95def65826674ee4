// parallel_record: what recording a pass on several threads buys (docs/chapter-20.md, "Beyond the
// book: recording on several threads"). A pass of N draws recorded the way chapters 15 to 18 record
// theirs -- per draw its vertex and index buffers bound, 112 bytes of push constants (a model matrix
// and a normal matrix), one vkCmdDrawIndexed; the pipeline bound when the material class changes --
// first into the frame's primary command buffer, then split into T secondary command buffers, each
// recorded by a thread of its own from a command pool of its own, executed in order inside one
// dynamic rendering (VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT). The threads stay alive
// between frames (a pool, as an engine keeps one); each frame resets its pool and records its
// share. What is timed: from the frame's start to its primary command buffer ended, every thread's
// share recorded -- the CPU time a frame's recording takes. Each form is submitted once and drawn
// (with --validation, checked by the Khronos layers).
//
//   parallel_record [--device NAME] [--draws "N ..."] [--threads "T ..."] [--repeats R] [--validation]
//
// Prints one line per N and form: the median and the minimum of R frames (default 30), in ms, and
// the median's ratio to the primary's.
#include <vulkan/vulkan.h>
#include <shaderc/shaderc.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/core/check.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"

namespace {

constexpr VkFormat kColor = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkExtent2D kExtent{256, 256};
constexpr uint32_t kClasses = 4;  // pipelines, as a scene's material classes; draws sorted by class

struct DrawConstants {  // what chapters 15 to 17 push per draw: model, then normal matrix (3 vec4)
    float model[16];
    float normal[12];
};
static_assert(sizeof(DrawConstants) == 112);

const char* kVertex = R"(#version 450
layout(push_constant) uniform Draw { mat4 model; vec4 normal[3]; } draw;
layout(location = 0) in vec2 position;
void main() { gl_Position = draw.model * vec4(position * 0.02, 0.0, 1.0); }
)";
const char* kFragment = R"(#version 450
layout(constant_id = 0) const float kShade = 1.0;
layout(location = 0) out vec4 color;
void main() { color = vec4(kShade, 0.5, 0.25, 1.0); }
)";

std::vector<uint32_t> compile(const char* source, shaderc_shader_kind kind, const char* name) {
    shaderc::Compiler compiler;
    shaderc::CompileOptions options;
    options.SetTargetEnvironment(shaderc_target_env_vulkan, shaderc_env_version_vulkan_1_2);
    auto result = compiler.CompileGlslToSpv(source, kind, name, options);
    if (result.GetCompilationStatus() != shaderc_compilation_status_success)
        throw std::runtime_error(result.GetErrorMessage());
    return {result.cbegin(), result.cend()};
}

VkShaderModule module(const common::Device& device, const std::vector<uint32_t>& code) {
    VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                  .codeSize = code.size() * sizeof(uint32_t),
                                  .pCode = code.data()};
    VkShaderModule m = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device.handle, &info, nullptr, &m));
    return m;
}

struct Pass {
    VkPipelineLayout layout = VK_NULL_HANDLE;
    std::array<VkPipeline, kClasses> pipelines{};
    common::Buffer vertices, indices;
    std::vector<DrawConstants> draws;
};

// Draws [first, last) of the pass: what each thread records of it, and the primary all of.
void recordDraws(VkCommandBuffer cmd, const Pass& pass, size_t first, size_t last) {
    VkViewport viewport{0.0f, 0.0f, float(kExtent.width), float(kExtent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, kExtent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    VkPipeline bound = VK_NULL_HANDLE;
    for (size_t i = first; i < last; ++i) {
        VkPipeline pipeline = pass.pipelines[i * kClasses / pass.draws.size()];
        if (pipeline != bound) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, bound = pipeline);
        VkDeviceSize offset = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &pass.vertices.handle, &offset);
        vkCmdBindIndexBuffer(cmd, pass.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        vkCmdPushConstants(cmd, pass.layout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(DrawConstants),
                           &pass.draws[i]);
        vkCmdDrawIndexed(cmd, 36, 1, 0, 0, 0);
    }
}

// A pool of threads that record a frame's shares: each its command pool and its secondary
// command buffer; `record` hands out one frame's work and returns once every share is recorded.
class Recorders {
public:
    Recorders(const common::Device& device, uint32_t count) : device_(device), shares_(count) {
        for (uint32_t i = 0; i < count; ++i) {
            VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                             .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                             .queueFamilyIndex = device.queueFamily};
            VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &shares_[i].pool));
            VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                                  .commandPool = shares_[i].pool,
                                                  .level = VK_COMMAND_BUFFER_LEVEL_SECONDARY,
                                                  .commandBufferCount = 1};
            VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &shares_[i].cmd));
        }
        for (uint32_t i = 0; i < count; ++i) threads_.emplace_back([this, i] { run(i); });
    }
    ~Recorders() {
        {
            std::lock_guard lock(mutex_);
            quit_ = true;
        }
        start_.notify_all();
        for (std::thread& thread : threads_) thread.join();
        for (Share& share : shares_) vkDestroyCommandPool(device_.handle, share.pool, nullptr);
    }
    Recorders(const Recorders&) = delete;
    Recorders& operator=(const Recorders&) = delete;

    // Every share of `pass` recorded; their secondary command buffers in order.
    std::vector<VkCommandBuffer> record(const Pass& pass) {
        {
            std::lock_guard lock(mutex_);
            pass_ = &pass;
            ++generation_;
            pending_ = uint32_t(shares_.size());
        }
        start_.notify_all();
        std::unique_lock lock(mutex_);
        done_.wait(lock, [&] { return pending_ == 0; });
        if (error_) std::rethrow_exception(error_);
        std::vector<VkCommandBuffer> buffers;
        for (const Share& share : shares_) buffers.push_back(share.cmd);
        return buffers;
    }

private:
    struct Share {
        VkCommandPool pool = VK_NULL_HANDLE;
        VkCommandBuffer cmd = VK_NULL_HANDLE;
    };

    void run(uint32_t index) {
        uint64_t seen = 0;
        for (;;) {
            const Pass* pass = nullptr;
            {
                std::unique_lock lock(mutex_);
                start_.wait(lock, [&] { return quit_ || generation_ != seen; });
                if (quit_) return;
                seen = generation_;
                pass = pass_;
            }
            try {
                Share& share = shares_[index];
                VK_CHECK(vkResetCommandPool(device_.handle, share.pool, 0));
                VkCommandBufferInheritanceRenderingInfo rendering{
                    .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_RENDERING_INFO,
                    .colorAttachmentCount = 1,
                    .pColorAttachmentFormats = &kColor,
                    .rasterizationSamples = VK_SAMPLE_COUNT_1_BIT};
                VkCommandBufferInheritanceInfo inheritance{
                    .sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO, .pNext = &rendering};
                VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                               .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT |
                                                        VK_COMMAND_BUFFER_USAGE_RENDER_PASS_CONTINUE_BIT,
                                               .pInheritanceInfo = &inheritance};
                VK_CHECK(vkBeginCommandBuffer(share.cmd, &begin));
                size_t n = pass->draws.size(), count = shares_.size();
                recordDraws(share.cmd, *pass, n * index / count, n * (index + 1) / count);
                VK_CHECK(vkEndCommandBuffer(share.cmd));
            } catch (...) {
                std::lock_guard lock(mutex_);
                error_ = std::current_exception();
            }
            {
                std::lock_guard lock(mutex_);
                --pending_;
            }
            done_.notify_all();
        }
    }

    const common::Device& device_;
    std::vector<Share> shares_;
    std::mutex mutex_;
    std::condition_variable start_, done_;
    const Pass* pass_ = nullptr;
    uint64_t generation_ = 0;
    uint32_t pending_ = 0;
    bool quit_ = false;
    std::exception_ptr error_;
    std::vector<std::thread> threads_;  // last: started once the rest exists
};

std::vector<uint32_t> numbers(const std::string& text) {
    std::vector<uint32_t> list;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
        char* end = nullptr;
        unsigned long value = std::strtoul(word.c_str(), &end, 10);
        if (word.empty() || *end != '\0' || value == 0 || value > 1'000'000)
            throw std::runtime_error("'" + word + "' is not a number from 1 to 1000000");
        list.push_back(uint32_t(value));
    }
    if (list.empty()) throw std::runtime_error("an empty list");
    return list;
}

int run(int argc, char** argv) {
    std::string deviceName;
    std::vector<uint32_t> drawCounts{1000, 10000, 100000}, threadCounts{1, 2, 4, 8, 16};
    uint32_t repeats = 30;
    bool validation = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
            return argv[++i];
        };
        if (arg == "--device")
            deviceName = value();
        else if (arg == "--draws")
            drawCounts = numbers(value());
        else if (arg == "--threads")
            threadCounts = numbers(value());
        else if (arg == "--repeats")
            repeats = std::min(numbers(value()).front(), 1000u);
        else if (arg == "--validation")
            validation = true;
        else
            throw std::runtime_error("unknown option " + arg);
    }
    for (uint32_t t : threadCounts)
        if (t > 64) throw std::runtime_error("at most 64 threads");

    common::Instance instance = common::createInstance("parallel_record", validation, {});
    common::Device device = common::createDevice(
        instance, VK_NULL_HANDLE, deviceName,
        {.minApiVersion = VK_API_VERSION_1_2, .dynamicRendering = true, .synchronization2 = true});
    std::printf("device %s (%s), %u hardware threads\n", device.properties.deviceName, device.driver.c_str(),
                std::thread::hardware_concurrency());
    common::Image target = common::createImage(device, kExtent, kColor, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                                               VK_IMAGE_ASPECT_COLOR_BIT, "parallel_record target");
    Pass pass;
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(DrawConstants)};
    pass.layout = common::createPipelineLayout(device, {}, {&push, 1}, "parallel_record layout");
    VkShaderModule vertex = module(device, compile(kVertex, shaderc_vertex_shader, "draw.vert"));
    VkShaderModule fragment = module(device, compile(kFragment, shaderc_fragment_shader, "draw.frag"));
    VkVertexInputBindingDescription binding{0, 2 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32_SFLOAT, 0};
    VkPipelineVertexInputStateCreateInfo vertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = 1,
        .pVertexBindingDescriptions = &binding,
        .vertexAttributeDescriptionCount = 1,
        .pVertexAttributeDescriptions = &attribute};
    VkPipelineRenderingCreateInfo renderingInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                .colorAttachmentCount = 1,
                                                .pColorAttachmentFormats = &kColor};
    for (uint32_t k = 0; k < kClasses; ++k) {
        float shade = float(k + 1) / float(kClasses);
        VkSpecializationMapEntry entry{0, 0, sizeof(float)};
        VkSpecializationInfo specialization{1, &entry, sizeof(float), &shade};
        pass.pipelines[k] = common::createGraphicsPipeline(
            device, VK_NULL_HANDLE,
            {.name = "parallel_record class " + std::to_string(k),
             .stages = {common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
                        common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment, &specialization)},
             .vertexInput = &vertexInput,
             .layout = pass.layout,
             .pNext = &renderingInfo});
    }
    vkDestroyShaderModule(device.handle, vertex, nullptr);
    vkDestroyShaderModule(device.handle, fragment, nullptr);
    // A cube's 36 indices over 8 corners, flattened to 2D (what is drawn does not matter here).
    std::vector<float> corners{-1,    -1,    1,    -1,    1,    1,    -1,    1,
                               -0.5f, -0.5f, 0.5f, -0.5f, 0.5f, 0.5f, -0.5f, 0.5f};
    std::vector<uint32_t> cube{0, 1, 2, 2, 3, 0, 4, 5, 6, 6, 7, 4, 0, 1, 5, 5, 4, 0,
                               2, 3, 7, 7, 6, 2, 1, 2, 6, 6, 5, 1, 0, 3, 7, 7, 4, 0};
    const VkMemoryPropertyFlags host =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    pass.vertices = common::createBuffer(device, corners.size() * sizeof(float),
                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, host, "parallel_record vertices");
    std::memcpy(pass.vertices.mapped, corners.data(), corners.size() * sizeof(float));
    pass.indices = common::createBuffer(device, cube.size() * sizeof(uint32_t),
                                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT, host, "parallel_record indices");
    std::memcpy(pass.indices.mapped, cube.data(), cube.size() * sizeof(uint32_t));

    VkCommandPool primaryPool = VK_NULL_HANDLE;
    VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                     .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                     .queueFamilyIndex = device.queueFamily};
    VK_CHECK(vkCreateCommandPool(device.handle, &poolInfo, nullptr, &primaryPool));
    VkCommandBuffer primary = VK_NULL_HANDLE;
    VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                          .commandPool = primaryPool,
                                          .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                          .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(device.handle, &allocInfo, &primary));
    VkFence done = VK_NULL_HANDLE;
    VkFenceCreateInfo fenceInfo{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device.handle, &fenceInfo, nullptr, &done));

    // One frame: the primary begun, the target to attachment, the rendering, `draws` recorded into
    // it (inline: the draws; else the secondaries executed), ended. Returns the milliseconds.
    auto frame = [&](bool secondaries, const std::function<std::vector<VkCommandBuffer>()>& shares) {
        auto start = std::chrono::steady_clock::now();
        VK_CHECK(vkResetCommandPool(device.handle, primaryPool, 0));
        VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        VK_CHECK(vkBeginCommandBuffer(primary, &begin));
        VkImageMemoryBarrier2 toAttachment = common::imageBarrier(
            target.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
        VkDependencyInfo dependency{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                                    .imageMemoryBarrierCount = 1,
                                    .pImageMemoryBarriers = &toAttachment};
        common::vk13.CmdPipelineBarrier2(primary, &dependency);
        VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = target.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
        VkRenderingInfo rendering{
            .sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
            .flags = secondaries ? VkRenderingFlags(VK_RENDERING_CONTENTS_SECONDARY_COMMAND_BUFFERS_BIT) : 0u,
            .renderArea = {{0, 0}, kExtent},
            .layerCount = 1,
            .colorAttachmentCount = 1,
            .pColorAttachments = &color};
        common::vk13.CmdBeginRendering(primary, &rendering);
        if (secondaries) {
            std::vector<VkCommandBuffer> buffers = shares();
            vkCmdExecuteCommands(primary, uint32_t(buffers.size()), buffers.data());
        } else {
            recordDraws(primary, pass, 0, pass.draws.size());
        }
        common::vk13.CmdEndRendering(primary);
        VK_CHECK(vkEndCommandBuffer(primary));
        double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return ms;
    };
    // The last frame of each form drawn once: the recorded commands are valid (--validation).
    auto submit = [&] {
        VkSubmitInfo info{
            .sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &primary};
        VK_CHECK(vkQueueSubmit(device.queue, 1, &info, done));
        VK_CHECK(vkWaitForFences(device.handle, 1, &done, VK_TRUE, UINT64_MAX));
        VK_CHECK(vkResetFences(device.handle, 1, &done));
    };
    auto summary = [](std::vector<double> times) {
        std::sort(times.begin(), times.end());
        return std::pair{times[times.size() / 2], times.front()};
    };

    for (uint32_t n : drawCounts) {
        pass.draws.assign(n, {});
        for (uint32_t i = 0; i < n; ++i) {  // placed on a grid, each its own matrix
            DrawConstants& d = pass.draws[i];
            for (int c = 0; c < 4; ++c) d.model[c * 5] = 1.0f;
            d.model[12] = -0.95f + 1.9f * float(i % 317) / 317.0f;
            d.model[13] = -0.95f + 1.9f * float((i / 317) % 317) / 317.0f;
            for (int c = 0; c < 3; ++c) d.normal[c * 5] = 1.0f;
        }
        std::vector<double> times;
        for (uint32_t r = 0; r < repeats + 3; ++r) {
            double ms = frame(false, {});
            if (r >= 3) times.push_back(ms);  // three warm-up frames
        }
        submit();
        auto [primaryMedian, primaryMin] = summary(times);
        std::printf("draws %7u  primary           median %9.3f ms  min %9.3f ms\n", n, primaryMedian,
                    primaryMin);
        for (uint32_t t : threadCounts) {
            Recorders recorders(device, t);
            times.clear();
            for (uint32_t r = 0; r < repeats + 3; ++r) {
                double ms = frame(true, [&] { return recorders.record(pass); });
                if (r >= 3) times.push_back(ms);
            }
            submit();
            auto [median, minimum] = summary(times);
            std::printf("draws %7u  %2u thread%s       median %9.3f ms  min %9.3f ms  %.2fx the primary's\n",
                        n, t, t == 1 ? " " : "s", median, minimum, median / primaryMedian);
            std::fflush(stdout);
        }
    }
    vkDestroyFence(device.handle, done, nullptr);
    vkDestroyCommandPool(device.handle, primaryPool, nullptr);
    common::destroyBuffer(device, pass.vertices);
    common::destroyBuffer(device, pass.indices);
    for (VkPipeline pipeline : pass.pipelines) vkDestroyPipeline(device.handle, pipeline, nullptr);
    vkDestroyPipelineLayout(device.handle, pass.layout, nullptr);
    common::destroyImage(device, target);
    common::destroyDevice(device);
    common::destroyInstance(instance);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "parallel_record: error: %s\n", e.what());
        return 2;
    }
}
