// Loading a scene's models, textures and materials onto the GPU.
#include "common/scene/gpu_scene.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "common/core/check.hpp"
#include "common/core/checked.hpp"
#include "common/core/files.hpp"
#include "common/core/report.hpp"
#include "common/model/animation.hpp"
#include "common/model/load_model.hpp"
#include "common/vk/debug_names.hpp"
#include "common/vk/texture.hpp"

namespace common {
namespace {

// A model's texture sampler (a glTF sampler, or the default: trilinear, repeat). A sampler
// without mipmaps reads level 0 only (maxLod 0.25 with nearest mip selection: minification and
// magnification filters stay apart, as OpenGL's non-mipmapped filters).
VkSampler createModelSampler(const Device& device, const SamplerDesc& desc) {
    auto filter = [](Filter f) { return f == Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; };
    auto wrap = [](Wrap w) {
        return w == Wrap::ClampToEdge      ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE
               : w == Wrap::MirroredRepeat ? VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT
                                           : VK_SAMPLER_ADDRESS_MODE_REPEAT;
    };
    VkSamplerCreateInfo info{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = filter(desc.magFilter),
        .minFilter = filter(desc.minFilter),
        .mipmapMode = desc.mipmaps && desc.mipFilter == Filter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                                       : VK_SAMPLER_MIPMAP_MODE_NEAREST,
        .addressModeU = wrap(desc.wrapU),
        .addressModeV = wrap(desc.wrapV),
        .addressModeW = wrap(desc.wrapU),
        .maxLod = desc.mipmaps ? VK_LOD_CLAMP_NONE : 0.25f,
        .borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK,
    };
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(device.handle, &info, nullptr, &sampler));
    nameObject(device.handle, sampler, "sampler");
    return sampler;
}

Pixels solid(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    return Pixels{1, 1, {r, g, b, a}};
}

// A texture to make, and from what. Materials that ask for the same one share it.
struct TextureRequest {
    enum class Kind : uint8_t {
        Albedo,  // `first` as sRGB colour; alpha from the first channel of `second` (OBJ map_d) when given
        Linear,  // `first` as it is, linear: normal, metal-rough (glTF) or occlusion maps
        MetalRough,  // OBJ: the book's metal-rough texture, G from `first` (map_Pr), B from `second` (map_Pm)
    };
    Kind kind;
    ImageSource first, second;
    auto operator<=>(const TextureRequest&) const = default;
};

// What a debugger calls a texture: its image file (or files).
std::string textureName(const TextureRequest& request) {
    std::string name =
        request.first.empty() ? "texture" : utf8(std::filesystem::path(request.first.name()).filename());
    if (!request.second.empty())
        name += " + " + utf8(std::filesystem::path(request.second.name()).filename());
    return name;
}

// What a debugger calls a mesh's buffer: "sponza.gltf mesh 12 vertices".
std::string meshName(const std::filesystem::path& model, size_t mesh, const char* what) {
    return utf8(model.filename()) + " mesh " + std::to_string(mesh) + " " + what;
}

// What a worker thread hands back: a texture's mip chain, or nothing for a missing file.
struct PreparedTexture {
    size_t request = 0;
    std::optional<MipChain> chain;
    bool hasAlpha = false;
};

// Every buffer and image has a memory allocation of its own, and a device allows only so many
// (maxMemoryAllocationCount: 4096 on many Windows drivers, however much memory they have): a
// scene that would need more is refused before it allocates them, in one line, rather than
// failing part-way. kRendererAllocations are kept for the renderer's own images and buffers.
constexpr uint64_t kRendererAllocations = 64;
void checkAllocationCount(const Device& device, uint64_t sceneAllocations,
                          const std::filesystem::path& file) {
    const uint64_t limit = device.properties.limits.maxMemoryAllocationCount;
    if (saturatingAdd(sceneAllocations, kRendererAllocations) > limit)
        throw InputError((file.empty() ? std::string() : utf8(file) + ": ") + "the scene needs " +
                         std::to_string(sceneAllocations) +
                         " memory allocations (one per mesh buffer and texture); this device allows " +
                         std::to_string(limit) + ", of which the renderer keeps " +
                         std::to_string(kRendererAllocations));
}

// The largest device-local heap and the part of it a scene may use: 3/4 (the rest is the
// G-buffer's, the swapchain's and the driver's).
struct MemoryBudget {
    VkDeviceSize heap = 0, scene = 0;
};
MemoryBudget memoryBudget(const Device& device) {
    MemoryBudget budget;
    for (uint32_t i = 0; i < device.memory.memoryHeapCount; ++i)
        if (device.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            budget.heap = std::max(budget.heap, device.memory.memoryHeaps[i].size);
    budget.scene = budget.heap / 4 * 3;
    return budget;
}

std::string mebibytes(uint64_t bytes) {  // rounded up
    return std::to_string(bytes / (1 << 20) + (bytes % (1 << 20) != 0));
}

// Makes every requested texture: decoding and mip chains on worker threads (one per core), the
// uploads on this thread, in staging batches of at most kStagingBudget bytes. At most
// kReadyPerWorker textures per worker wait for their upload, so host memory holds a few textures
// at a time however many the scene has.
class TextureBuilder {
public:
    static constexpr size_t kStagingBudget = size_t{48} << 20;
    static constexpr size_t kReadyPerWorker = 2;

    TextureBuilder(const Device& device) : device_(device) {
        srgbMips_ = linearFilterable(device, VK_FORMAT_R8G8B8A8_SRGB);
        unormMips_ = linearFilterable(device, VK_FORMAT_R8G8B8A8_UNORM);
    }

    // The id of a texture to make (the same request twice: the same id).
    uint32_t request(const TextureRequest& request) {
        auto [it, added] = ids_.try_emplace(request, uint32_t(requests_.size()));
        if (added) requests_.push_back(request);
        return it->second;
    }

    // Makes the requested textures into scene.textures; per request, its index there, or
    // kMissing where its files do not exist.
    static constexpr uint32_t kMissing = UINT32_MAX;
    std::vector<uint32_t> build(StagingBatch& batch, GpuScene& scene) {
        checkMemoryBudget(scene);
        std::vector<uint32_t> index(requests_.size(), kMissing);
        size_t workers = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
        workers = std::min(workers, requests_.size());
        std::vector<std::thread> threads;
        for (size_t w = 0; w < workers; ++w) threads.emplace_back([this, workers] { work(workers); });
        size_t staged = 0;
        try {
            for (size_t received = 0; received < requests_.size(); ++received) {
                PreparedTexture prepared;
                {
                    std::unique_lock lock(mutex_);
                    changed_.wait(lock, [&] { return !ready_.empty() || error_; });
                    if (error_) break;
                    prepared = std::move(ready_.front());
                    ready_.pop_front();
                }
                changed_.notify_all();
                if (!prepared.chain) continue;
                if (staged > 0 && staged + prepared.chain->bytes.size() > kStagingBudget) {
                    endStaging(device_, batch);  // the copies so far done, their staging memory freed
                    batch = beginStaging(device_);
                    staged = 0;
                }
                staged += prepared.chain->bytes.size();
                index[prepared.request] = uint32_t(scene.textures.size());
                scene.textures.push_back(uploadMipChain(device_, batch, *prepared.chain,
                                                        textureName(requests_[prepared.request])));
                scene.textureHasAlpha.push_back(prepared.hasAlpha);
            }
        } catch (...) {
            stop();
            for (std::thread& t : threads) t.join();
            throw;
        }
        stop();
        for (std::thread& t : threads) t.join();
        if (error_) std::rethrow_exception(error_);
        return index;
    }

private:
    void stop() {
        std::lock_guard lock(mutex_);
        if (!error_) stopped_ = true;
        changed_.notify_all();
    }

    void work(size_t workers) {
        for (;;) {
            size_t request;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(
                    lock, [&] { return error_ || stopped_ || ready_.size() < kReadyPerWorker * workers; });
                if (error_ || stopped_ || next_ >= requests_.size()) return;
                request = next_++;
            }
            PreparedTexture prepared;
            try {
                prepared = prepare(request);
            } catch (...) {
                std::lock_guard lock(mutex_);
                if (!error_) error_ = std::current_exception();
                changed_.notify_all();
                return;
            }
            std::lock_guard lock(mutex_);
            ready_.push_back(std::move(prepared));
            changed_.notify_all();
        }
    }

    // What the scene will hold in device memory -- its meshes, uploaded already, and every
    // texture with its mip levels, from the images' headers before any is decoded -- against the
    // largest device-local heap: refused beyond 3/4 of it (the rest is the G-buffer's, the
    // swapchain's and the driver's), in one line naming both.
    void checkMemoryBudget(const GpuScene& scene) {
        checkAllocationCount(device_, 2 * scene.meshes.size() + scene.textures.size() + requests_.size(), {});
        const uint32_t maxDimension = device_.properties.limits.maxImageDimension2D;
        uint64_t meshBytes = 0, texelBytes = 0;
        for (const GpuMesh& mesh : scene.meshes)
            meshBytes = saturatingAdd(
                meshBytes, saturatingAdd(mesh.ownsVertices ? mesh.vertices.size : 0, mesh.indices.size));
        for (const TextureRequest& request : requests_) {
            std::optional<ImageExtent> extent;
            for (const ImageSource* source : {&request.first, &request.second}) {
                if (extent || source->empty()) continue;
                std::error_code ec;
                if (source->embedded)
                    extent = readImageExtent(source->embedded->data(), source->embedded->size(),
                                             source->name(), maxDimension);
                else if (std::filesystem::exists(source->file, ec))
                    extent = readImageExtent(source->file, maxDimension);
            }
            if (extent) texelBytes = saturatingAdd(texelBytes, mipChainBytes(*extent));
        }
        const MemoryBudget memory = memoryBudget(device_);
        const VkDeviceSize heap = memory.heap, budget = memory.scene;
        const uint64_t need = saturatingAdd(meshBytes, texelBytes);
        auto mib = [](uint64_t bytes) {
            return std::to_string(bytes / (1 << 20) + (bytes % (1 << 20) != 0));
        };
        if (need > budget)
            throw InputError("the scene needs " + mib(need) + " MiB of device memory (meshes " +
                             mib(meshBytes) + " MiB, textures with their mip levels " + mib(texelBytes) +
                             " MiB); this device's largest device-local memory heap has " +
                             std::to_string(heap >> 20) + " MiB, of which a scene may use 3/4 (" +
                             std::to_string(budget >> 20) + " MiB)");
    }

    PreparedTexture prepare(size_t index) {
        const TextureRequest& request = requests_[index];
        std::optional<Pixels> a = read(request.first), b = read(request.second);
        std::optional<Pixels> pixels;
        switch (request.kind) {
            case TextureRequest::Kind::Albedo:
                if (!a && !b) break;
                pixels = a ? std::move(*a)
                           : Pixels{b->width, b->height, std::vector<uint8_t>(b->rgba.size(), 255)};
                if (b) copyChannel(*b, 0, *pixels, 3);
                break;
            case TextureRequest::Kind::Linear:
                pixels = std::move(a);
                break;
            case TextureRequest::Kind::MetalRough:
                if (!a && !b) break;
                {
                    const Pixels& size = a ? *a : *b;
                    pixels = Pixels{size.width, size.height, std::vector<uint8_t>(size.rgba.size(), 255)};
                    if (a) copyChannel(*a, 0, *pixels, 1);
                    if (b) copyChannel(*b, 0, *pixels, 2);
                }
                break;
        }
        PreparedTexture prepared{index, std::nullopt, false};
        if (!pixels) return prepared;
        for (size_t i = 3; i < pixels->rgba.size() && !prepared.hasAlpha; i += 4)
            prepared.hasAlpha = pixels->rgba[i] < 255;
        bool srgb = request.kind == TextureRequest::Kind::Albedo;
        // Only a base colour's alpha is coverage (glTF's baseColorTexture); the other maps' alpha
        // means nothing, and their channels are averaged each on its own.
        prepared.chain =
            makeMipChain(*pixels, srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                         srgb ? srgbMips_ : unormMips_, srgb ? MipAlpha::Coverage : MipAlpha::Independent);
        return prepared;
    }

    // An image's pixels; nothing (with one warning) for a file that does not exist.
    std::optional<Pixels> read(const ImageSource& source) {
        if (source.empty()) return std::nullopt;
        uint32_t maxDimension = device_.properties.limits.maxImageDimension2D;
        if (source.embedded)
            return decodePixels(source.embedded->data(), source.embedded->size(), source.name(),
                                maxDimension);
        std::error_code ec;
        if (!std::filesystem::exists(source.file, ec)) {
            std::lock_guard lock(mutex_);
            warn("texture '" + utf8(source.file) + "' not found; using the default texture");
            return std::nullopt;
        }
        return loadPixels(source.file, maxDimension);
    }

    // Copies channel `from` of `source` into channel `to` of `target`, nearest-sampled when the
    // sizes differ.
    static void copyChannel(const Pixels& source, int from, Pixels& target, int to) {
        for (uint32_t y = 0; y < target.height; ++y)
            for (uint32_t x = 0; x < target.width; ++x) {
                size_t sx = size_t(x) * source.width / target.width,
                       sy = size_t(y) * source.height / target.height;
                target.rgba[(size_t(y) * target.width + x) * 4 + size_t(to)] =
                    source.rgba[(sy * source.width + sx) * 4 + size_t(from)];
            }
    }

    const Device& device_;
    bool srgbMips_ = false, unormMips_ = false;
    std::vector<TextureRequest> requests_;
    std::map<TextureRequest, uint32_t> ids_;
    std::mutex mutex_;  // guards what follows
    std::condition_variable changed_;
    size_t next_ = 0;
    std::deque<PreparedTexture> ready_;
    bool stopped_ = false;
    std::exception_ptr error_;
};

// A material while its textures are being made: request ids where GpuMaterial will hold images.
struct PendingMaterial {
    GpuMaterial material;
    AlphaMode alphaMode = AlphaMode::Auto;
    uint32_t albedo = kNone, normal = kNone, metalRough = kNone, occlusion = kNone;
    static constexpr uint32_t kNone = UINT32_MAX;
};

}  // namespace

void setDrawModel(const GpuScene& scene, Draw& draw, const glm::mat4& model) {
    const GpuMesh& mesh = scene.meshes[draw.mesh];
    draw.model = model;
    draw.normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    draw.center = glm::vec3(model * glm::vec4((mesh.boundsMin + mesh.boundsMax) * 0.5f, 1.0f));
}

GpuScene loadGpuScene(const Device& device, const Scene& scene, ModelCache& models, GpuSceneOptions wanted) {
    GpuScene gpu;
    StagingBatch batch = beginStaging(device);
    gpu.textures.push_back(
        uploadTexture(device, batch, solid(255, 255, 255, 255), VK_FORMAT_R8G8B8A8_UNORM, "white"));
    gpu.textures.push_back(
        uploadTexture(device, batch, solid(128, 128, 255, 255), VK_FORMAT_R8G8B8A8_UNORM, "flat normal"));
    gpu.textureHasAlpha = {false, false};
    std::map<SamplerDesc, uint32_t> samplers;
    auto sampler = [&](const SamplerDesc& desc) {
        auto [it, added] = samplers.try_emplace(desc, uint32_t(gpu.samplers.size()));
        if (added) gpu.samplers.push_back(createModelSampler(device, desc));
        return it->second;
    };
    sampler(SamplerDesc{});  // [0]: the default
    TextureBuilder textures(device);
    std::vector<PendingMaterial> pending;
    std::map<std::filesystem::path, uint32_t> firstMesh;  // per model: its meshes' index in gpu.meshes
    std::map<std::filesystem::path, uint32_t>
        firstMirroredMesh;                                     // the same, turned round (mirrored transforms)
    std::map<std::filesystem::path, uint32_t> plainMaterials;  // per model without overrides: its materials
    bool firstBounds = true;
    uint64_t meshBytes = 0;  // of the meshes uploaded so far

    for (uint32_t instanceIndex = 0; instanceIndex < scene.models.size(); ++instanceIndex) {
        const ModelInstance& instance = scene.models[instanceIndex];
        const ModelData& model = loadModelCached(models, instance.file);
        const std::filesystem::path key = modelKey(instance.file);  // one upload per file, however spelled
        // The glTF specification's rule for every chapter (3.7.4 "Instantiation"): a transform of
        // negative determinant (a mirror) makes clockwise triangles the front faces. Such a scene
        // transform draws a copy of the model's meshes whose indices run the other way round,
        // with the same vertex buffers, so culling and gl_FrontFacing stay right in every pass.
        glm::mat4 matrix = instance.transform.matrix();
        const bool mirrored = glm::determinant(glm::dmat3(glm::dmat4(matrix))) < 0.0;
        std::map<std::filesystem::path, uint32_t>& uploaded = mirrored ? firstMirroredMesh : firstMesh;
        if (!uploaded.count(key)) {
            const bool copy = mirrored && firstMesh.count(key);  // the vertices are there already
            if (mirrored && !copy) {
                // Unmirrored first (never drawn unless another instance is), then the mirror.
                firstMesh[key] = uint32_t(gpu.meshes.size());
            }
            const uint32_t base =
                uint32_t(gpu.meshes.size()) + (mirrored && !copy ? uint32_t(model.meshes.size()) : 0);
            uploaded[key] = base;
            const uint64_t newMeshes = (mirrored && !copy ? 2 : 1) * model.meshes.size();
            checkAllocationCount(device, 2 * (gpu.meshes.size() + newMeshes), instance.file);
            // The meshes' device memory, model by model before each is uploaded (the textures are
            // added from their headers before they are decoded, in TextureBuilder).
            for (const MeshData& mesh : model.meshes) {
                uint64_t indexBytes = saturatingMul(mesh.indices.size(), sizeof(uint32_t));
                if (!copy)
                    meshBytes = saturatingAdd(
                        meshBytes,
                        saturatingAdd(saturatingMul(mesh.vertices.size(), sizeof(Vertex)), indexBytes));
                if (mirrored) meshBytes = saturatingAdd(meshBytes, indexBytes);
            }
            if (const MemoryBudget memory = memoryBudget(device); meshBytes > memory.scene)
                throw InputError(
                    utf8(instance.file) + ": the scene's meshes need " + mebibytes(meshBytes) +
                    " MiB of device memory with it; this device's largest device-local memory heap has " +
                    std::to_string(memory.heap >> 20) + " MiB, of which a scene may use 3/4 (" +
                    std::to_string(memory.scene >> 20) + " MiB)");
            // A chapter before chapter-17 draws a skinned model in its rest pose.
            Pose rest;
            if (!copy && !model.rig.empty() && !wanted.skins) {
                poseRig(model.rig, -1, 0.0, rest);
                warn(utf8(instance.file) +
                     ": its skins and animations are played by chapter-17 (drawn here in its "
                     "rest pose)");
            }
            if (!copy)
                for (const MeshData& mesh : model.meshes) {
                    GpuMesh out;
                    std::vector<Vertex> posed;
                    if (!rest.joints.empty() && !mesh.skin.empty()) {
                        posed.reserve(mesh.vertices.size());
                        for (size_t v = 0; v < mesh.vertices.size(); ++v) {
                            SkinnedVertex s = skinVertex(mesh.vertices[v], mesh.skin[v], rest.joints);
                            posed.push_back({glm::vec3(s.position), glm::vec3(s.normal), glm::vec3(s.tangent),
                                             glm::vec3(s.bitangent), mesh.vertices[v].uv});
                        }
                    }
                    const std::vector<Vertex>& vertices = posed.empty() ? mesh.vertices : posed;
                    VkBufferUsageFlags usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
                    if (wanted.skins && !mesh.skin.empty()) usage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
                    const VkBufferUsageFlags addressed =
                        wanted.deviceAddresses ? VkBufferUsageFlags(VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)
                                               : 0u;
                    usage |= addressed;
                    const VkBufferUsageFlags indexUsage =
                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT | addressed |
                        (wanted.copyableIndices ? VkBufferUsageFlags(VK_BUFFER_USAGE_TRANSFER_SRC_BIT) : 0u);
                    out.vertices =
                        uploadStaged(device, batch, vertices.data(), vertices.size() * sizeof(Vertex), usage,
                                     meshName(instance.file, gpu.meshes.size(), "vertices"));
                    out.indices = uploadStaged(device, batch, mesh.indices.data(),
                                               mesh.indices.size() * sizeof(uint32_t), indexUsage,
                                               meshName(instance.file, gpu.meshes.size(), "indices"));
                    out.indexCount = uint32_t(mesh.indices.size());
                    out.boundsMin = out.boundsMax = vertices.front().position;
                    for (const Vertex& v : vertices) {
                        out.boundsMin = glm::min(out.boundsMin, v.position);
                        out.boundsMax = glm::max(out.boundsMax, v.position);
                    }
                    gpu.meshes.push_back(out);
                }
            if (mirrored)
                for (size_t i = 0; i < model.meshes.size(); ++i) {
                    GpuMesh out = gpu.meshes[firstMesh[key] + i];
                    out.ownsVertices = false;
                    std::vector<uint32_t> turned = model.meshes[i].indices;
                    for (size_t k = 0; k + 2 < turned.size(); k += 3) std::swap(turned[k + 1], turned[k + 2]);
                    out.indices = uploadStaged(
                        device, batch, turned.data(), turned.size() * sizeof(uint32_t),
                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                            (wanted.deviceAddresses
                                 ? VkBufferUsageFlags(VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT)
                                 : 0u) |
                            (wanted.copyableIndices ? VkBufferUsageFlags(VK_BUFFER_USAGE_TRANSFER_SRC_BIT)
                                                    : 0u),
                        meshName(instance.file, gpu.meshes.size(), "mirrored indices"));
                    gpu.meshes.push_back(out);
                }
        }

        for (const auto& [name, unused] : instance.materials) {
            bool known = false;
            for (const MaterialData& m : model.materials) known = known || m.name == name;
            if (!known)
                throw InputError(utf8(instance.file) + ": has no material '" + name +
                                 "' (named in the scene's material overrides)");
        }
        uint32_t materialBase = uint32_t(pending.size());
        if (instance.materials.empty() && plainMaterials.count(key)) {
            materialBase = plainMaterials[key];
        } else {
            if (instance.materials.empty()) plainMaterials[key] = materialBase;
            for (const MaterialData& m : model.materials) {
                MaterialOverride o;
                if (auto it = instance.materials.find(m.name); it != instance.materials.end()) o = it->second;
                PendingMaterial p;
                GpuMaterial& material = p.material;
                material.diffuse = o.diffuse.value_or(m.diffuse);
                material.roughness = o.roughness.value_or(m.roughness);
                material.metallic = o.metallic.value_or(m.metallic);
                material.normalScale = m.normalScale;
                material.occlusionStrength = m.occlusionStrength;
                material.alphaCutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : 0.5f;
                material.doubleSided = m.doubleSided;
                p.alphaMode = m.alphaMode;
                // An override replaces a texture's image; the model's sampler stays.
                TextureRef albedo = m.diffuseTexture, normal = m.normalTexture;
                if (o.diffuseTexture) albedo.image = ImageSource{.file = *o.diffuseTexture};
                if (o.normalTexture) normal.image = ImageSource{.file = *o.normalTexture};
                using Kind = TextureRequest::Kind;
                if (!albedo.empty() || !m.alphaTexture.empty()) {
                    p.albedo = textures.request({Kind::Albedo, albedo.image, m.alphaTexture.image});
                    material.albedo.sampler =
                        sampler(albedo.empty() ? m.alphaTexture.sampler : albedo.sampler);
                }
                if (wanted.normalMaps && !normal.empty()) {
                    p.normal = textures.request({Kind::Linear, normal.image, {}});
                    material.normal.sampler = sampler(normal.sampler);
                }
                if (wanted.metalRoughMaps && !m.metalRoughTexture.empty()) {
                    p.metalRough = textures.request({Kind::Linear, m.metalRoughTexture.image, {}});
                    material.metalRough.sampler = sampler(m.metalRoughTexture.sampler);
                } else if (wanted.metalRoughMaps &&
                           (!m.roughnessTexture.empty() || !m.metallicTexture.empty())) {
                    p.metalRough = textures.request(
                        {Kind::MetalRough, m.roughnessTexture.image, m.metallicTexture.image});
                }
                if (wanted.occlusionMaps && !m.occlusionTexture.empty()) {
                    p.occlusion = textures.request({Kind::Linear, m.occlusionTexture.image, {}});
                    material.occlusion.sampler = sampler(m.occlusionTexture.sampler);
                }
                pending.push_back(p);
            }
        }

        // Every draw is recorded each frame: a scene that places a model of many meshes many
        // times is refused before the product is made.
        if (gpu.draws.size() + model.meshes.size() + model.repeats.size() > kMaxSceneDraws ||
            pending.size() > kMaxSceneDraws)
            throw InputError(
                utf8(instance.file) + ": the scene places it as model " + std::to_string(instanceIndex + 1) +
                ", past " + std::to_string(kMaxSceneDraws) +
                " draws (or materials) in all, models times their meshes; at most that many are drawn");
        auto addDraw = [&](uint32_t mesh, uint32_t material) {
            gpu.draws.push_back(Draw{.mesh = uploaded[key] + mesh,
                                     .material = materialBase + material,
                                     .instance = instanceIndex});
            setDrawModel(gpu, gpu.draws.back(), matrix);
            gpu.triangles += model.meshes[mesh].indices.size() / 3;
        };
        for (size_t i = 0; i < model.meshes.size(); ++i) addDraw(uint32_t(i), model.meshes[i].material);
        for (const MeshRepeat& repeat : model.repeats) addDraw(repeat.mesh, repeat.material);
        for (int corner = 0; corner < 8; ++corner) {
            glm::dvec3 local = boxCorner(corner, glm::dvec3(model.boundsMin), glm::dvec3(model.boundsMax));
            // In double, then checked: a model at 1e15 scaled by 1e30 has corners no float holds,
            // and the bounds feed the camera, the cascades and the culling.
            glm::dvec3 placed = glm::dvec3(glm::dmat4(matrix) * glm::dvec4(local, 1.0));
            for (int axis = 0; axis < 3; ++axis)
                if (!(std::abs(placed[axis]) <= double(kMaxModelCoordinate))) {
                    char text[64];
                    std::snprintf(text, sizeof(text), "%g", placed[axis]);
                    throw InputError(utf8(instance.file) + ": the scene's transform (model " +
                                     std::to_string(instanceIndex) + ") places a corner of its bounds at " +
                                     text + " on an axis; coordinates from -1e15 to 1e15 are drawn");
                }
            glm::vec3 world(placed);
            gpu.boundsMin = firstBounds ? world : glm::min(gpu.boundsMin, world);
            gpu.boundsMax = firstBounds ? world : glm::max(gpu.boundsMax, world);
            firstBounds = false;
        }
    }

    // The textures, then the materials that use them (a missing file leaves the default).
    std::vector<uint32_t> made = textures.build(batch, gpu);
    auto image = [&](uint32_t request, uint32_t fallback) {
        return request == PendingMaterial::kNone || made[request] == TextureBuilder::kMissing ? fallback
                                                                                              : made[request];
    };
    for (PendingMaterial& p : pending) {
        GpuMaterial& material = p.material;
        material.albedo.image = image(p.albedo, kWhiteTexture);
        material.normal.image = image(p.normal, kFlatNormalTexture);
        material.metalRough.image = image(p.metalRough, kWhiteTexture);
        material.occlusion.image = image(p.occlusion, kWhiteTexture);
        material.alphaTested = p.alphaMode == AlphaMode::Mask ||
                               (p.alphaMode == AlphaMode::Auto &&
                                (material.diffuse.a < 1.0f || gpu.textureHasAlpha[material.albedo.image]));
        gpu.materials.push_back(material);
    }
    endStaging(device, batch);
    return gpu;
}

void destroyGpuScene(const Device& device, GpuScene& scene) {
    for (VkSampler sampler : scene.samplers) vkDestroySampler(device.handle, sampler, nullptr);
    for (Image& texture : scene.textures) destroyImage(device, texture);
    for (GpuMesh& mesh : scene.meshes) {
        if (mesh.ownsIndices) destroyBuffer(device, mesh.indices);
        if (mesh.ownsVertices) destroyBuffer(device, mesh.vertices);
    }
    scene = {};
}

void describeSceneVertexInput(SceneVertexInput& input, uint32_t attributes) {
    input.binding = {.binding = 0, .stride = sizeof(Vertex), .inputRate = VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription all[5] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, position))},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, normal))},
        {2, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, tangent))},
        {3, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, bitangent))},
        {4, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(Vertex, uv))},
    };
    uint32_t count = 0;
    for (uint32_t location = 0; location < 5; ++location)
        if (attributes & (1u << location)) input.attributes[count++] = all[location];
    input.state = {
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = 1,
        .pVertexBindingDescriptions = &input.binding,
        .vertexAttributeDescriptionCount = count,
        .pVertexAttributeDescriptions = input.attributes.data(),
    };
}

std::vector<bool> usedMaterials(const GpuScene& scene) {
    std::vector<bool> used(scene.materials.size(), false);
    for (const Draw& draw : scene.draws) used[draw.material] = true;
    return used;
}

}  // namespace common
