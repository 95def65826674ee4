// chapter-15-lab: the skinning study (skinning_study.hpp).
#include "skinning_study.hpp"

#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/gtc/quaternion.hpp>

#include "common/core/check.hpp"
#include "common/core/files.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/barriers.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/commands.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/descriptors.hpp"
#include "common/vk/device.hpp"
#include "common/vk/image.hpp"
#include "common/vk/instance.hpp"
#include "common/vk/pipeline.hpp"

namespace {

constexpr int kMaxInfluences = 8;

// A generated figure at rest, and the skinning matrix (world * inverse bind) of each joint in the
// pose the study measures, in double.
struct Figure {
    std::string name;
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::array<uint16_t, kMaxInfluences>> joints;  // heaviest first
    std::vector<std::array<double, kMaxInfluences>> weights;   // sum to 1
    int influences = 4;                                        // the figure's own count
    std::vector<uint32_t> indices;
    std::vector<glm::dmat4> pose;
    uint32_t rings = 0, ringSize = 0;  // vertices in rings of ringSize, ring after ring
    double radius = 0.0;               // every ring's radius at rest
    double size = 0.0;                 // the rest pose's bounding box diagonal
};

// A tube along +x from 0 to `length`, `rings` x `sides`, its influences from `weigh`.
template <typename Weigh>
void tube(Figure& figure, double length, double radius, uint32_t rings, uint32_t sides, Weigh weigh) {
    figure.rings = rings + 1;
    figure.ringSize = sides + 1;
    figure.radius = radius;
    for (uint32_t r = 0; r <= rings; ++r) {
        double x = length * double(r) / double(rings);
        std::array<uint16_t, kMaxInfluences> j{};
        std::array<double, kMaxInfluences> w{};
        weigh(x, j, w);
        for (uint32_t s = 0; s <= sides; ++s) {
            double a = 2.0 * glm::pi<double>() * double(s) / double(sides);
            glm::dvec3 n(0.0, std::cos(a), std::sin(a));
            figure.positions.push_back(glm::dvec3(x, 0.0, 0.0) + radius * n);
            figure.normals.push_back(n);
            figure.joints.push_back(j);
            figure.weights.push_back(w);
        }
    }
    for (uint32_t r = 0; r < rings; ++r)
        for (uint32_t s = 0; s < sides; ++s) {
            uint32_t a = r * (sides + 1) + s, b = a + sides + 1;
            figure.indices.insert(figure.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
        }
    glm::dvec3 extent(length, 2.0 * radius, 2.0 * radius);
    figure.size = glm::length(extent);
}

// The candy wrapper: a tube 2 long, its halves on two joints blended over the middle (smoothstep),
// the second twisted 180 degrees about the tube's axis. Linear blend skinning collapses its middle
// ring onto the axis; dual quaternions keep its radius.
Figure candyWrapper(uint32_t rings, uint32_t sides) {
    Figure figure;
    figure.name = "candy wrapper";
    figure.influences = 4;  // two used: the others weigh 0, as a glTF JOINTS_0/WEIGHTS_0 would
    tube(figure, 2.0, 0.25, rings, sides, [](double x, auto& j, auto& w) {
        double t = glm::clamp(x - 0.5, 0.0, 1.0);
        t = t * t * (3.0 - 2.0 * t);
        j = {1, 0, 0, 0, 0, 0, 0, 0};
        w = {t, 1.0 - t, 0, 0, 0, 0, 0, 0};
        if (t < 0.5) std::swap(j[0], j[1]), std::swap(w[0], w[1]);
    });
    glm::dmat4 twist = glm::translate(glm::dmat4(1.0), glm::dvec3(1.0, 0.0, 0.0)) *
                       glm::rotate(glm::dmat4(1.0), glm::pi<double>(), glm::dvec3(1.0, 0.0, 0.0)) *
                       glm::translate(glm::dmat4(1.0), glm::dvec3(-1.0, 0.0, 0.0));
    figure.pose = {glm::dmat4(1.0), twist};
    return figure;
}

// A tentacle 4 long of 16 joints a quarter apart, each vertex on the 8 joints nearest it (weights
// by a Gaussian of its distance to each segment's middle, the heaviest first), curled: every joint
// turned 20 degrees about z and 10 about x from its parent.
Figure tentacle(uint32_t rings, uint32_t sides) {
    constexpr int kJoints = 16;
    constexpr double kSegment = 0.25;
    Figure figure;
    figure.name = "tentacle";
    figure.influences = 8;
    tube(figure, kJoints * kSegment, 0.2, rings, sides, [](double x, auto& j, auto& w) {
        std::array<std::pair<double, int>, kJoints> all;
        for (int k = 0; k < kJoints; ++k) {
            double d = (x - (k + 0.5) * kSegment) / kSegment;
            all[size_t(k)] = {std::exp(-d * d), k};
        }
        std::sort(all.begin(), all.end(), [](auto a, auto b) { return a.first > b.first; });
        double sum = 0.0;
        for (int k = 0; k < kMaxInfluences; ++k) sum += all[size_t(k)].first;
        for (int k = 0; k < kMaxInfluences; ++k) {
            j[size_t(k)] = uint16_t(all[size_t(k)].second);
            w[size_t(k)] = all[size_t(k)].first / sum;
        }
    });
    glm::dmat4 world(1.0);
    for (int k = 0; k < kJoints; ++k) {
        if (k > 0) world = glm::translate(world, glm::dvec3(kSegment, 0.0, 0.0));
        world = world * glm::rotate(glm::dmat4(1.0), glm::radians(20.0), glm::dvec3(0.0, 0.0, 1.0)) *
                glm::rotate(glm::dmat4(1.0), glm::radians(10.0), glm::dvec3(1.0, 0.0, 0.0));
        glm::dmat4 restWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(k * kSegment, 0.0, 0.0));
        figure.pose.push_back(world * glm::inverse(restWorld));
    }
    return figure;
}

enum Method { LinearBlend = 0, DualQuaternion = 1 };

// A form of skinning the study measures.
struct Form {
    int figure = 0;             // 0 tentacle, 1 candy wrapper
    bool vertexShader = false;  // in every pass's vertex shader, not once by the compute pass
    Method method = LinearBlend;
    bool halfJoints = false;
    int influences = 4;
};

// A joint's dual quaternion (real, dual), from a rigid skinning matrix.
std::array<glm::dvec4, 2> dualQuaternion(const glm::dmat4& m) {
    glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(m)));
    glm::dvec3 t(m[3]);
    glm::dquat dual = glm::dquat(0.0, t.x, t.y, t.z) * q * 0.5;
    return {glm::dvec4(q.x, q.y, q.z, q.w), glm::dvec4(dual.x, dual.y, dual.z, dual.w)};
}

glm::dvec3 rotate(const glm::dvec4& q, const glm::dvec3& v) {
    glm::dvec3 u(q);
    return v + 2.0 * glm::cross(u, glm::cross(u, v) + q.w * v);
}

// Per joint, what the reference reads: the matrix, its normal matrix, its dual quaternion.
struct ReferenceJoints {
    std::vector<glm::dmat3> normal;
    std::vector<std::array<glm::dvec4, 2>> dual;
};

ReferenceJoints referenceJoints(const Figure& figure) {
    ReferenceJoints joints;
    for (const glm::dmat4& m : figure.pose) {
        joints.normal.push_back(glm::transpose(glm::inverse(glm::dmat3(m))));
        joints.dual.push_back(dualQuaternion(m));
    }
    return joints;
}

// The reference: vertex `i` skinned in double by `method` with `influences` of its weights
// (renormalised when fewer than the figure has).
void referenceVertex(const Figure& figure, const ReferenceJoints& joints, Method method, int influences,
                     size_t i, glm::dvec3& position, glm::dvec3& normal) {
    double sum = 0.0;
    for (int k = 0; k < influences; ++k) sum += figure.weights[i][size_t(k)];
    position = normal = glm::dvec3(0.0);
    glm::dvec4 real(0.0), dual(0.0), first(0.0);
    for (int k = 0; k < influences; ++k) {
        double w = figure.weights[i][size_t(k)] / sum;
        uint16_t j = figure.joints[i][size_t(k)];
        if (method == LinearBlend) {
            position += w * glm::dvec3(figure.pose[j] * glm::dvec4(figure.positions[i], 1.0));
            normal += w * (joints.normal[j] * figure.normals[i]);
        } else {
            const auto& [r, d] = joints.dual[j];
            if (k == 0) first = r;
            double s = glm::dot(first, r) < 0.0 ? -w : w;  // the same hemisphere as the first
            real += s * r;
            dual += s * d;
        }
    }
    if (method == DualQuaternion) {
        double len = glm::length(real);
        real /= len;
        dual /= len;
        glm::dvec3 t = 2.0 * (real.w * glm::dvec3(dual) - dual.w * glm::dvec3(real) +
                              glm::cross(glm::dvec3(real), glm::dvec3(dual)));
        position = rotate(real, figure.positions[i]) + t;
        normal = rotate(real, figure.normals[i]);
    }
}

// The reference's own check: a vertex on one joint moves rigidly, so both methods must agree
// there (a wrong dual quaternion in dualQuaternion() would show, which the palette shares).
void checkReference(const Figure& figure, const ReferenceJoints& joints) {
    for (size_t i = 0; i < figure.positions.size(); ++i) {
        if (figure.weights[i][0] != 1.0) continue;
        glm::dvec3 p[2], n[2];
        referenceVertex(figure, joints, LinearBlend, figure.influences, i, p[0], n[0]);
        referenceVertex(figure, joints, DualQuaternion, figure.influences, i, p[1], n[1]);
        if (glm::length(p[0] - p[1]) > 1e-12 * figure.size || glm::length(n[0] - n[1]) > 1e-12)
            throw common::Failure(
                "the skinning study's reference: dual quaternions and matrices disagree on a "
                "vertex of one joint");
    }
}

uint32_t floatWord(float f) {
    uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}

// The palette as the shader reads it (skinning_study.glsl): per joint 24 floats or 12 words of
// halves (linear blend), or 8 floats (dual quaternions).
std::vector<uint32_t> paletteWords(const Figure& figure, const ReferenceJoints& joints, const Form& form) {
    std::vector<uint32_t> words;
    for (size_t j = 0; j < figure.pose.size(); ++j) {
        if (form.method == DualQuaternion) {
            for (const glm::dvec4& q : joints.dual[j])
                for (int c = 0; c < 4; ++c) words.push_back(floatWord(float(q[c])));
            continue;
        }
        std::array<float, 24> values{};
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) values[size_t(3 * c + r)] = float(figure.pose[j][c][r]);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) values[size_t(12 + 3 * c + r)] = float(joints.normal[j][c][r]);
        if (form.halfJoints)
            for (size_t k = 0; k < 24; k += 2) words.push_back(glm::packHalf2x16({values[k], values[k + 1]}));
        else
            for (float f : values) words.push_back(floatWord(f));
    }
    return words;
}

// Per vertex: `influences` joints in 16 bits, two to a word, then as many weights (renormalised).
std::vector<uint32_t> influenceWords(const Figure& figure, int influences) {
    std::vector<uint32_t> words;
    words.reserve(figure.positions.size() * size_t(influences + influences / 2));
    for (size_t i = 0; i < figure.positions.size(); ++i) {
        for (int k = 0; k < influences; k += 2)
            words.push_back(uint32_t(figure.joints[i][size_t(k)]) |
                            (uint32_t(figure.joints[i][size_t(k + 1)]) << 16));
        double sum = 0.0;
        for (int k = 0; k < influences; ++k) sum += figure.weights[i][size_t(k)];
        for (int k = 0; k < influences; ++k)
            words.push_back(floatWord(float(figure.weights[i][size_t(k)] / sum)));
    }
    return words;
}

// What one form measured.
struct Result {
    // GPU time, ms: the compute pass, the four passes, both (median, fastest, slowest run).
    double skinMs = 0.0, drawMs = 0.0, totalMs = 0.0, totalMin = 0.0, totalMax = 0.0;
    // Against the form itself in double (its method and influences, exact joints): position error
    // / the figure's size, largest and 99th percentile; normal error where the reference has one.
    double maxError = 0.0, p99Error = 0.0, maxNormalDegrees = 0.0;
    // Against the method in double with every influence the figure has (what it was made with).
    double maxErrorEveryInfluence = 0.0;
    double narrowest = 0.0;     // the narrowest ring's mean radius / its rest radius
    uint64_t sceneSamples = 0;  // the scene pass's fragments that passed the depth test
};

void compare(const Figure& figure, const ReferenceJoints& joints, const Form& form, const float* skinned,
             Result& result) {
    size_t n = figure.positions.size();
    std::vector<double> errors(n);
    result.maxNormalDegrees = result.maxErrorEveryInfluence = 0.0;
    auto finite = [](double e) { return std::isfinite(e) ? e : INFINITY; };
    for (size_t i = 0; i < n; ++i) {
        glm::dvec3 position, normal, every, everyNormal;
        referenceVertex(figure, joints, form.method, form.influences, i, position, normal);
        referenceVertex(figure, joints, form.method, figure.influences, i, every, everyNormal);
        glm::dvec3 gpu(skinned[6 * i], skinned[6 * i + 1], skinned[6 * i + 2]);
        glm::dvec3 gpuNormal(skinned[6 * i + 3], skinned[6 * i + 4], skinned[6 * i + 5]);
        errors[i] = finite(glm::length(gpu - position) / figure.size);
        result.maxErrorEveryInfluence =
            std::max(result.maxErrorEveryInfluence, finite(glm::length(gpu - every) / figure.size));
        double length = glm::length(normal);
        if (length < 1e-6) continue;  // linear blend's collapsed ring: no normal to compare with
        glm::dvec3 a = normal / length;
        double gl = glm::length(gpuNormal);
        double angle = gl > 0.0 && std::isfinite(gl) ? std::atan2(glm::length(glm::cross(a, gpuNormal / gl)),
                                                                  glm::dot(a, gpuNormal / gl))
                                                     : glm::pi<double>();
        result.maxNormalDegrees = std::max(result.maxNormalDegrees, glm::degrees(angle));
    }
    std::vector<double> sorted = errors;
    size_t p99 = std::min(n - 1, size_t(std::ceil(0.99 * double(n))) - 1);
    std::nth_element(sorted.begin(), sorted.begin() + long(p99), sorted.end());
    result.p99Error = sorted[p99];
    result.maxError = *std::max_element(errors.begin(), errors.end());
    // The shape: each ring's mean distance from its centre, against the rest radius.
    result.narrowest = INFINITY;
    for (uint32_t r = 0; r < figure.rings; ++r) {
        glm::dvec3 centre(0.0);
        for (uint32_t s = 0; s + 1 < figure.ringSize; ++s) {  // the seam's vertex repeats the first
            const float* v = skinned + 6 * (size_t(r) * figure.ringSize + s);
            centre += glm::dvec3(v[0], v[1], v[2]);
        }
        centre /= double(figure.ringSize - 1);
        double radius = 0.0;
        for (uint32_t s = 0; s + 1 < figure.ringSize; ++s) {
            const float* v = skinned + 6 * (size_t(r) * figure.ringSize + s);
            radius += glm::length(glm::dvec3(v[0], v[1], v[2]) - centre);
        }
        result.narrowest = std::min(result.narrowest, radius / double(figure.ringSize - 1) / figure.radius);
    }
}

std::string formName(const Form& form) {
    return std::string(form.vertexShader ? "vertex shader x4" : "compute once") + ", " +
           (form.method == LinearBlend ? "linear blend" : "dual quaternion") + ", " +
           (form.halfJoints ? "fp16" : "fp32") + " joints, " + std::to_string(form.influences) +
           " influences";
}

struct Sizes {
    uint32_t tubeRings, tubeSides, tentacleRings, tentacleSides, repeats;
};

// The GPU side shared by the forms: layouts, the passes' targets, the queries.
struct Study {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout computeLayout = VK_NULL_HANDLE, drawLayout = VK_NULL_HANDLE;
    common::Image color, depth;
    std::array<common::Image, 3> cascades;
    VkQueryPool timestamps = VK_NULL_HANDLE, samples = VK_NULL_HANDLE;
    uint64_t tickMask = ~0ull;  // timestampValidBits
    double msPerTick = 0.0;
    static constexpr VkFormat kColor = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kDepth = VK_FORMAT_D32_SFLOAT;
    static constexpr uint32_t kViewSize = 1024, kCascadeSize = 2048;
};

struct FormPipelines {
    VkPipeline compute = VK_NULL_HANDLE, scene = VK_NULL_HANDLE, cascade = VK_NULL_HANDLE,
               store = VK_NULL_HANDLE;
};

// One form on one figure: its buffers, descriptor set and pipelines, and what it measured.
struct FormRun {
    Form form;
    const Figure* figure = nullptr;
    common::Buffer rest, influences, palette, indices, skinned, readback;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    FormPipelines pipelines;
    std::array<glm::mat4, 4> views{};
    std::vector<double> skinTimes, drawTimes;
    Result result;
};

// Into `pipelines` one by one, so that what was made is destroyed if a later one fails.
void makePipelines(const common::Device& device, const Study& study, const Form& form,
                   FormPipelines& pipelines) {
    struct Constants {
        int32_t method, half, influences, skinHere;
    };
    std::array<VkSpecializationMapEntry, 4> entries;
    for (uint32_t k = 0; k < 4; ++k) entries[k] = {k, 4 * k, 4};
    auto make = [&](bool vertexStage, bool skinHere, auto&& build) {
        Constants constants{int32_t(form.method), form.halfJoints ? 1 : 0, form.influences, skinHere ? 1 : 0};
        // The compute shader has the forms' three constants; the vertex shader one more.
        VkSpecializationInfo info{vertexStage ? 4u : 3u, entries.data(), sizeof(constants), &constants};
        return build(&info);
    };
    pipelines.compute = make(false, false, [&](const VkSpecializationInfo* info) {
        common::ShaderModule module(device, "chapter-15-lab/skinning_study.comp");
        VkComputePipelineCreateInfo createInfo{
            .sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
            .stage = common::shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module, info),
            .layout = study.computeLayout};
        VkPipeline pipeline = VK_NULL_HANDLE;
        VK_CHECK(vkCreateComputePipelines(device.handle, VK_NULL_HANDLE, 1, &createInfo, nullptr, &pipeline));
        common::nameObject(device.handle, pipeline, "skinning study: compute " + formName(form));
        return pipeline;
    });
    auto graphics = [&](bool skinHere, bool store, bool scene) {
        return make(true, skinHere, [&](const VkSpecializationInfo* info) {
            common::ShaderModule vertex(device, store ? "chapter-15-lab/skinning_study-store.vert"
                                                      : "chapter-15-lab/skinning_study.vert");
            common::ShaderModule fragment(device, "chapter-15-lab/skinning_study.frag");
            VkFormat color = Study::kColor;
            VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                    .colorAttachmentCount = scene ? 1u : 0u,
                                                    .pColorAttachmentFormats = &color,
                                                    .depthAttachmentFormat = Study::kDepth};
            common::GraphicsPipelineDesc desc{
                .name = "skinning study: " + std::string(scene ? "scene " : "cascade ") + formName(form),
                .depthTest = true,
                .depthWrite = true,
                .colorAttachmentCount = scene ? 1u : 0u,
                .layout = study.drawLayout,
                .pNext = &rendering};
            desc.stages.push_back(common::shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex, info));
            if (scene) desc.stages.push_back(common::shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment));
            return common::createGraphicsPipeline(device, VK_NULL_HANDLE, desc);
        });
    };
    pipelines.scene = graphics(form.vertexShader, false, true);
    pipelines.cascade = graphics(form.vertexShader, false, false);
    if (form.vertexShader) pipelines.store = graphics(true, true, true);
}

// The four passes' view-projections, fitted to the posed figure (`posed`: its reference
// positions): a perspective view of it, and three orthographic cascades looking down at it, the
// first twice its size across (the figure half the map), each next twice as wide.
std::array<glm::mat4, 4> passViews(const std::vector<glm::dvec3>& posed, double figureSize) {
    glm::dvec3 min(INFINITY), max(-INFINITY);
    for (const glm::dvec3& p : posed) min = glm::min(min, p), max = glm::max(max, p);
    glm::vec3 centre((min + max) * 0.5);
    float size = float(std::max(glm::length(max - min), 0.5 * figureSize));
    std::array<glm::mat4, 4> views;
    views[0] = glm::perspective(glm::radians(60.0f), 1.0f, 0.05f * size, 10.0f * size) *
               glm::lookAt(centre + glm::vec3(0.3f, 0.4f, 1.2f) * size, centre, glm::vec3(0, 1, 0));
    for (int k = 0; k < 3; ++k) {
        float half = size * float(1 << k);
        views[size_t(k + 1)] =
            glm::ortho(-half, half, -half, half, 0.0f, 4.0f * size) *
            glm::lookAt(centre + glm::vec3(0.4f, 1.0f, 0.3f) * size * 2.0f, centre, glm::vec3(0, 0, 1));
    }
    return views;
}

void renderingBarriers(VkCommandBuffer cmd, const Study& study) {
    VkPipelineStageFlags2 depthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    std::vector<VkImageMemoryBarrier2> barriers;
    for (VkImage image :
         {study.depth.handle, study.cascades[0].handle, study.cascades[1].handle, study.cascades[2].handle})
        barriers.push_back(common::imageBarrier(
            image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, depthStages,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depthStages,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT));
    barriers.push_back(common::imageBarrier(
        study.color.handle, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT));
    common::pipelineBarrier(cmd, barriers.data(), uint32_t(barriers.size()));
}

// Draws the figure in the scene pass (counting its samples when `countSamples`) and, with
// `cascadesToo`, the three cascades.
void recordPasses(VkCommandBuffer cmd, const Study& study, const FormRun& run, VkPipeline scene,
                  bool cascadesToo, bool countSamples) {
    for (uint32_t pass = 0; pass < (cascadesToo ? 4u : 1u); ++pass) {
        uint32_t size = pass == 0 ? Study::kViewSize : Study::kCascadeSize;
        VkRenderingAttachmentInfo color{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = study.color.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .clearValue = {.color = {{0.0f, 0.0f, 0.0f, 1.0f}}}};
        VkRenderingAttachmentInfo depth{
            .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
            .imageView = pass == 0 ? study.depth.view : study.cascades[pass - 1].view,
            .imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
            .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
            .clearValue = {.depthStencil = {1.0f, 0}}};
        VkRenderingInfo rendering{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                  .renderArea = {{0, 0}, {size, size}},
                                  .layerCount = 1,
                                  .colorAttachmentCount = pass == 0 ? 1u : 0u,
                                  .pColorAttachments = &color,
                                  .pDepthAttachment = &depth};
        common::vk13.CmdBeginRendering(cmd, &rendering);
        VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        VkRect2D scissor{{0, 0}, {size, size}};
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass == 0 ? scene : run.pipelines.cascade);
        vkCmdPushConstants(cmd, study.drawLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                           &run.views[pass]);
        vkCmdBindIndexBuffer(cmd, run.indices.handle, 0, VK_INDEX_TYPE_UINT32);
        if (pass == 0 && countSamples) vkCmdBeginQuery(cmd, study.samples, 0, VK_QUERY_CONTROL_PRECISE_BIT);
        vkCmdDrawIndexed(cmd, uint32_t(run.figure->indices.size()), 1, 0, 0, 0);
        if (pass == 0 && countSamples) vkCmdEndQuery(cmd, study.samples, 0);
        common::vk13.CmdEndRendering(cmd);
    }
}

VkMemoryBarrier2 memoryBarrier(VkPipelineStageFlags2 srcStages, VkAccessFlags2 srcAccess,
                               VkPipelineStageFlags2 dstStages, VkAccessFlags2 dstAccess) {
    return {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
            .srcStageMask = srcStages,
            .srcAccessMask = srcAccess,
            .dstStageMask = dstStages,
            .dstAccessMask = dstAccess};
}

void barrier(VkCommandBuffer cmd, const VkMemoryBarrier2& memory) {
    VkDependencyInfo dependency{
        .sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1, .pMemoryBarriers = &memory};
    common::vk13.CmdPipelineBarrier2(cmd, &dependency);
}

// The compute pass: every vertex skinned once into `skinned`, for the passes and copies after it.
void recordSkinning(VkCommandBuffer cmd, const Study& study, const FormRun& run) {
    uint32_t count = uint32_t(run.figure->positions.size());
    // The previous submission's passes and copy are done reading the skinned vertices.
    barrier(cmd, memoryBarrier(VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT));
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, run.pipelines.compute);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, study.computeLayout, 0, 1, &run.set, 0,
                            nullptr);
    vkCmdPushConstants(cmd, study.computeLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, 4, &count);
    vkCmdDispatch(cmd, (count + 31) / 32, 1, 1);
    barrier(cmd, memoryBarrier(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                               VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT));
}

// A form's buffers, set and pipelines; then the check: skinned once (by the compute pass, or by
// the scene pass's vertex shader, which then writes what it skinned), read back and compared.
// For the vertex shader's form the skinned buffer is then filled with NaN, so that its timed
// passes, which must skin for themselves, draw nothing if they read it instead.
// Into `run` step by step, so that what was made is destroyed if a later step fails.
void createRun(const common::Device& device, const Study& study, const Figure& figure,
               const ReferenceJoints& joints, const std::vector<glm::dvec3>& posed, const Form& form,
               FormRun& run) {
    run.form = form;
    run.figure = &figure;
    uint32_t count = uint32_t(figure.positions.size());
    std::vector<float> rest;
    rest.reserve(size_t(count) * 6);
    for (uint32_t i = 0; i < count; ++i)
        for (const glm::dvec3& v : {figure.positions[i], figure.normals[i]})
            rest.insert(rest.end(), {float(v.x), float(v.y), float(v.z)});
    std::vector<uint32_t> influences = influenceWords(figure, form.influences);
    std::vector<uint32_t> palette = paletteWords(figure, joints, form);
    VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    common::StagingBatch batch = common::beginStaging(device);
    run.rest = common::uploadStaged(device, batch, rest.data(), rest.size() * 4, storage,
                                    "skinning study: rest pose");
    run.influences = common::uploadStaged(device, batch, influences.data(), influences.size() * 4, storage,
                                          "skinning study: influences");
    run.palette = common::uploadStaged(device, batch, palette.data(), palette.size() * 4, storage,
                                       "skinning study: palette");
    run.indices = common::uploadStaged(device, batch, figure.indices.data(), figure.indices.size() * 4,
                                       VK_BUFFER_USAGE_INDEX_BUFFER_BIT, "skinning study: indices");
    common::endStaging(device, batch);
    VkDeviceSize skinnedBytes = VkDeviceSize(count) * 24;
    run.skinned = common::createBuffer(
        device, skinnedBytes, storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "skinning study: skinned");
    run.readback =
        common::createBuffer(device, skinnedBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                             "skinning study: readback");
    run.pool = common::createDescriptorPool(device, 1, {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4}},
                                            "skinning study: " + formName(form));
    run.set = common::allocateDescriptorSet(device, run.pool, study.setLayout, "skinning study");
    const common::Buffer* bound[] = {&run.rest, &run.influences, &run.palette, &run.skinned};
    for (uint32_t b = 0; b < 4; ++b)
        common::writeBufferDescriptor(device, run.set, b, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, bound[b]->handle,
                                      bound[b]->size);
    makePipelines(device, study, form, run.pipelines);
    run.views = passViews(posed, figure.size);

    VkCommandBuffer cmd = common::beginOneTimeCommands(device);
    if (form.vertexShader) {
        renderingBarriers(cmd, study);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, study.drawLayout, 0, 1, &run.set, 0,
                                nullptr);
        recordPasses(cmd, study, run, run.pipelines.store, false, false);
        barrier(cmd,
                memoryBarrier(VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT));
    } else {
        recordSkinning(cmd, study, run);
    }
    VkBufferCopy region{0, 0, skinnedBytes};
    vkCmdCopyBuffer(cmd, run.skinned.handle, run.readback.handle, 1, &region);
    barrier(cmd, memoryBarrier(VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                               VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT));
    if (form.vertexShader) {
        barrier(cmd, memoryBarrier(VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                   VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT));
        vkCmdFillBuffer(cmd, run.skinned.handle, 0, VK_WHOLE_SIZE, 0xffffffffu);  // NaN
        barrier(cmd,
                memoryBarrier(VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                              VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT));
    }
    common::submitOneTimeCommands(device, cmd);
    compare(figure, joints, form, static_cast<const float*>(run.readback.mapped), run.result);
}

// One timed submission of a form: the compute pass (if any) between timestamps 0 and 1, the four
// passes between 1 and 2; the scene pass's samples counted.
void timeRun(const common::Device& device, const Study& study, FormRun& run) {
    VkCommandBuffer cmd = common::beginOneTimeCommands(device);
    vkCmdResetQueryPool(cmd, study.timestamps, 0, 3);
    vkCmdResetQueryPool(cmd, study.samples, 0, 1);
    renderingBarriers(cmd, study);
    // After the images' transitions: the forms are timed from here alike.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, study.timestamps, 0);
    if (!run.form.vertexShader) recordSkinning(cmd, study, run);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, study.timestamps, 1);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, study.drawLayout, 0, 1, &run.set, 0,
                            nullptr);
    recordPasses(cmd, study, run, run.pipelines.scene, true, true);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, study.timestamps, 2);
    common::submitOneTimeCommands(device, cmd);
    std::array<uint64_t, 3> ticks{};
    VK_CHECK(vkGetQueryPoolResults(device.handle, study.timestamps, 0, 3, sizeof(ticks), ticks.data(), 8,
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    VK_CHECK(vkGetQueryPoolResults(device.handle, study.samples, 0, 1, 8, &run.result.sceneSamples, 8,
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    auto elapsed = [&](int a, int b) {
        return double((ticks[size_t(b)] - ticks[size_t(a)]) & study.tickMask) * study.msPerTick;
    };
    run.skinTimes.push_back(elapsed(0, 1));
    run.drawTimes.push_back(elapsed(1, 2));
}

void summarise(FormRun& run) {
    auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    std::vector<double> totals;
    for (size_t k = 0; k < run.drawTimes.size(); ++k)
        totals.push_back(run.drawTimes[k] + (run.form.vertexShader ? 0.0 : run.skinTimes[k]));
    run.result.skinMs = run.form.vertexShader ? 0.0 : median(run.skinTimes);
    run.result.drawMs = median(run.drawTimes);
    run.result.totalMs = median(totals);
    run.result.totalMin = *std::min_element(totals.begin(), totals.end());
    run.result.totalMax = *std::max_element(totals.begin(), totals.end());
}

void destroyRun(const common::Device& device, FormRun& run) {
    for (VkPipeline p :
         {run.pipelines.compute, run.pipelines.scene, run.pipelines.cascade, run.pipelines.store})
        vkDestroyPipeline(device.handle, p, nullptr);
    vkDestroyDescriptorPool(device.handle, run.pool, nullptr);
    for (common::Buffer* b :
         {&run.rest, &run.influences, &run.palette, &run.indices, &run.skinned, &run.readback})
        common::destroyBuffer(device, *b);
    run = {};
}

void destroyStudy(const common::Device& device, Study& study) {
    vkDestroyQueryPool(device.handle, study.samples, nullptr);
    vkDestroyQueryPool(device.handle, study.timestamps, nullptr);
    for (common::Image& cascade : study.cascades) common::destroyImage(device, cascade);
    common::destroyImage(device, study.depth);
    common::destroyImage(device, study.color);
    vkDestroyPipelineLayout(device.handle, study.drawLayout, nullptr);
    vkDestroyPipelineLayout(device.handle, study.computeLayout, nullptr);
    vkDestroyDescriptorSetLayout(device.handle, study.setLayout, nullptr);
    study = {};
}

// Into `study` step by step, so that what was made is destroyed if a later step fails.
void createStudy(const common::Device& device, Study& study) {
    auto storageBinding = [](uint32_t index) {
        return common::binding(index, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                               VK_SHADER_STAGE_COMPUTE_BIT | VK_SHADER_STAGE_VERTEX_BIT);
    };
    study.setLayout = common::createDescriptorSetLayout(
        device, {storageBinding(0), storageBinding(1), storageBinding(2), storageBinding(3)},
        "skinning study");
    VkPushConstantRange computePush{VK_SHADER_STAGE_COMPUTE_BIT, 0, 4};
    VkPushConstantRange drawPush{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
    study.computeLayout = common::createPipelineLayout(device, {&study.setLayout, 1}, {&computePush, 1},
                                                       "skinning study: compute");
    study.drawLayout =
        common::createPipelineLayout(device, {&study.setLayout, 1}, {&drawPush, 1}, "skinning study: draw");
    VkImageUsageFlags depthUsage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    study.color = common::createImage(device, {Study::kViewSize, Study::kViewSize}, Study::kColor,
                                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                                      "skinning study: scene colour");
    study.depth = common::createImage(device, {Study::kViewSize, Study::kViewSize}, Study::kDepth, depthUsage,
                                      VK_IMAGE_ASPECT_DEPTH_BIT, "skinning study: scene depth");
    for (common::Image& cascade : study.cascades)
        cascade = common::createImage(device, {Study::kCascadeSize, Study::kCascadeSize}, Study::kDepth,
                                      depthUsage, VK_IMAGE_ASPECT_DEPTH_BIT, "skinning study: cascade");
    VkQueryPoolCreateInfo timestampInfo{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                        .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                        .queryCount = 3};
    VK_CHECK(vkCreateQueryPool(device.handle, &timestampInfo, nullptr, &study.timestamps));
    VkQueryPoolCreateInfo samplesInfo{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                      .queryType = VK_QUERY_TYPE_OCCLUSION,
                                      .queryCount = 1};
    VK_CHECK(vkCreateQueryPool(device.handle, &samplesInfo, nullptr, &study.samples));
    study.tickMask = device.timestampValidBits >= 64 ? ~0ull : (1ull << device.timestampValidBits) - 1;
    study.msPerTick = double(device.properties.limits.timestampPeriod) * 1e-6;
}

void writeCsv(const std::filesystem::path& path, const std::vector<FormRun>& runs,
              const common::Device& device) {
    common::removeStaleTemporaries(path);
    common::RegisteredTemporary written(path);
    {
        std::ofstream out(written.path);
        out << "figure,vertices,pass,method,joints,influences,skin_ms,draw_ms,total_ms,total_ms_min,total_ms_"
               "max,"
               "max_error,p99_error,max_normal_degrees,max_error_every_influence,narrowest_ring,scene_"
               "samples,"
               "device\n";
        for (const FormRun& run : runs) {
            const Result& r = run.result;
            char line[640];
            std::snprintf(
                line, sizeof(line),
                "%s,%zu,%s,%s,%s,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.3e,%.3e,%.4g,%.3e,%.4f,%llu,\"%s\"\n",
                run.figure->name.c_str(), run.figure->positions.size(),
                run.form.vertexShader ? "vertex shader" : "compute",
                run.form.method == LinearBlend ? "linear blend" : "dual quaternion",
                run.form.halfJoints ? "fp16" : "fp32", run.form.influences, r.skinMs, r.drawMs, r.totalMs,
                r.totalMin, r.totalMax, r.maxError, r.p99Error, r.maxNormalDegrees, r.maxErrorEveryInfluence,
                r.narrowest, static_cast<unsigned long long>(r.sceneSamples), device.properties.deviceName);
            out << line;
        }
        out.flush();
        if (!out) throw common::Failure("cannot write '" + common::utf8(path) + "'");
    }
    std::error_code ec;
    std::filesystem::rename(written.path, path, ec);
    if (ec) {
        std::filesystem::remove(written.path, ec);
        throw common::Failure("cannot write '" + common::utf8(path) + "'");
    }
}

// What the study refuses: everything that is not its own, the device's or validation.
void refuseOtherOptions(const common::Options& options) {
    auto refuse = [](const std::string& what) {
        throw common::InputError("--skinning-study draws its own figures and no frames: no " + what);
    };
    if (!options.scene.empty()) refuse("--scene");
    if (!options.model.empty()) refuse("--model");
    if (!options.bookScene.empty()) refuse("--book-scene");
    for (const auto& [name, value] : options.choices)
        if (name != "skinning-study-size") refuse("--" + name);
    for (const auto& [name, value] : options.values)
        if (name != "skinning-study") refuse("--" + name);
    for (const std::string& name : options.switches) refuse("--" + name);
    if (!options.screenshot.empty()) refuse("--screenshot");
    if (options.benchmark) refuse("--benchmark");
    if (!options.json.empty()) refuse("--json");
    if (options.view != 0) refuse("--view");
    if (options.frames != 0) refuse("--frames");
    if (options.resizeTo) refuse("--resize");
    if (options.targetFormat) refuse("--target-format");
    const common::Options defaults;
    if (options.width != defaults.width || options.height != defaults.height) refuse("--width or --height");
    if (options.framesInFlight != defaults.framesInFlight) refuse("--frames-in-flight");
}

}  // namespace

bool skinningStudyRequested(const common::Options& options) {
    return options.values.count("skinning-study") != 0;
}

//> run-study
void runSkinningStudy(const common::Options& options) {
    refuseOtherOptions(options);
    std::filesystem::path csv = options.values.at("skinning-study");
    std::error_code ec;
    std::filesystem::path dir = csv.parent_path().empty() ? std::filesystem::path(".") : csv.parent_path();
    std::filesystem::file_status status = std::filesystem::symlink_status(csv, ec);
    bool exists = std::filesystem::exists(status);
    if (exists && !std::filesystem::is_regular_file(status))
        throw common::InputError("cannot write '" + common::utf8(csv) + "': not a regular file");
    if (!std::filesystem::is_directory(dir, ec) || !common::isWritable(dir) ||
        (exists && !common::isWritable(csv)))
        throw common::InputError("cannot write '" + common::utf8(csv) + "'");
    // medium: about 66 000 vertices a figure; small, for the tests: about a thousand; large: about a million.
    const Sizes kSizes[] = {{512, 128, 1024, 64, 9}, {32, 16, 64, 16, 3}, {2048, 512, 4096, 256, 25}};
    auto size = options.choices.find("skinning-study-size");
    const Sizes& sizes = kSizes[size == options.choices.end() ? 0 : size->second];
    std::vector<Figure> figures{tentacle(sizes.tentacleRings, sizes.tentacleSides),
                                candyWrapper(sizes.tubeRings, sizes.tubeSides)};
    std::vector<ReferenceJoints> joints;
    std::vector<std::vector<glm::dvec3>> posed(figures.size());
    for (size_t f = 0; f < figures.size(); ++f) {
        joints.push_back(referenceJoints(figures[f]));
        checkReference(figures[f], joints[f]);
        for (size_t i = 0; i < figures[f].positions.size(); ++i) {
            glm::dvec3 normal;
            referenceVertex(figures[f], joints[f], LinearBlend, figures[f].influences, i,
                            posed[f].emplace_back(), normal);
        }
    }
    // The forms: chapter-17's (compute, linear blend, fp32) with all 8 influences and with 4, then
    // one change at a time; on the candy wrapper, linear blend against dual quaternions.
    const std::vector<Form> forms{
        {.figure = 0, .influences = 8},
        {.figure = 0, .influences = 4},
        {.figure = 0, .vertexShader = true, .influences = 8},
        {.figure = 0, .halfJoints = true, .influences = 8},
        {.figure = 0, .method = DualQuaternion, .influences = 8},
        {.figure = 1},
        {.figure = 1, .vertexShader = true},
        {.figure = 1, .method = DualQuaternion},
    };

    common::Instance instance = common::createInstance("chapter-15-lab", options.validation, {});
    common::Device device;
    Study study;
    std::vector<FormRun> runs;
    // Whatever fails, what was made is destroyed before the error goes on.
    auto destroyAll = [&] {
        if (device.handle) {
            vkDeviceWaitIdle(device.handle);
            for (FormRun& run : runs) destroyRun(device, run);
            destroyStudy(device, study);
            common::destroyDevice(device);
        }
        common::destroyInstance(instance);
    };
    try {
        device = common::createDevice(instance, VK_NULL_HANDLE, options.device,
                                      {.dynamicRendering = true,
                                       .synchronization2 = true,
                                       .vertexStores = true,
                                       .preciseOcclusion = true});
        if (device.timestampValidBits == 0 ||
            device.properties.limits.timestampComputeAndGraphics == VK_FALSE ||
            device.properties.limits.timestampPeriod <= 0.0f)
            throw common::Failure("this device's queue has no timestamps: the study cannot time the forms");
        createStudy(device, study);
        std::printf("chapter-15-lab: skinning study on %s (%u timed runs a form, interleaved; median)\n",
                    device.properties.deviceName, sizes.repeats);
        for (const Form& form : forms) {
            size_t f = size_t(form.figure);
            createRun(device, study, figures[f], joints[f], posed[f], form, runs.emplace_back());
        }
        // Interleaved: the forms take turns, so that a machine's slower moments fall on all of them;
        // after one round untimed (first uses: caches, the driver's lazy work).
        for (FormRun& run : runs) timeRun(device, study, run);
        for (FormRun& run : runs) run.skinTimes.clear(), run.drawTimes.clear();
        for (uint32_t repeat = 0; repeat < sizes.repeats; ++repeat)
            for (FormRun& run : runs) timeRun(device, study, run);
        std::printf("%-14s %8s  %-58s %8s %8s %10s %10s %9s %9s\n", "figure", "vertices", "form", "skin ms",
                    "draw ms", "max error", "p99 error", "normal °", "narrowest");
        for (FormRun& run : runs) {
            summarise(run);
            const Result& r = run.result;
            std::printf("%-14s %8zu  %-58s %8.3f %8.3f %10.2e %10.2e %9.4f %9.3f\n", run.figure->name.c_str(),
                        run.figure->positions.size(), formName(run.form).c_str(), r.skinMs, r.drawMs,
                        r.maxError, r.p99Error, r.maxNormalDegrees, r.narrowest);
        }
        writeCsv(csv, runs, device);
        std::printf("chapter-15-lab: wrote %s\n", common::utf8(csv).c_str());
    } catch (...) {
        destroyAll();
        throw;
    }
    Result chapter17 = runs[0].result;
    destroyAll();

    // chapter-17's form (compute, linear blend, fp32, every influence) within chapter-17's bound.
    if (chapter17.maxError > 1e-5 || chapter17.maxNormalDegrees > 0.01)
        throw common::Failure(
            "the compute pass's linear blend skinning is beyond its bound (1e-5 of the "
            "figure's size, 0.01 degrees)");
}
//< run-study
