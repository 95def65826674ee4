// Loading a scene's models, textures and materials onto the GPU.
#include "common/gpu_scene.hpp"

#include <cstddef>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "common/check.hpp"
#include "common/files.hpp"
#include "common/texture.hpp"

namespace common {
namespace {

Pixels solid(uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    return Pixels{1, 1, {r, g, b, a}};
}

// Uploads each distinct texture once; a file that does not exist becomes the fallback with one
// warning, a file that exists but cannot be decoded is an InputError.
class TextureLoader {
public:
    TextureLoader(const Device& device, StagingBatch& batch, GpuScene& scene)
        : device_(device), batch_(batch), scene_(scene) {
        scene_.textures.push_back(
            uploadTexture(device_, batch_, solid(255, 255, 255, 255), VK_FORMAT_R8G8B8A8_UNORM));
        scene_.textures.push_back(
            uploadTexture(device_, batch_, solid(128, 128, 255, 255), VK_FORMAT_R8G8B8A8_UNORM));
        scene_.textureHasAlpha = {false, false};
    }

    // Albedo (sRGB) with alpha taken from the red channel of `alpha` (map_d) when given.
    uint32_t albedo(const std::filesystem::path& color, const std::filesystem::path& alpha) {
        return load(
            {color, alpha, "albedo"},
            [&] {
                std::optional<Pixels> rgb = read(color), a = read(alpha);
                if (!rgb && !a) return std::optional<Pixels>();
                Pixels out =
                    rgb ? *rgb : Pixels{a->width, a->height, std::vector<uint8_t>(a->rgba.size(), 255)};
                if (a) copyChannel(*a, 0, out, 3);
                return std::optional<Pixels>(out);
            },
            VK_FORMAT_R8G8B8A8_SRGB, 0);
    }

    uint32_t normal(const std::filesystem::path& path) {
        return load(
            {path, {}, "normal"}, [&] { return read(path); }, VK_FORMAT_R8G8B8A8_UNORM, 1);
    }

    // The book's metal-rough texture: G = roughness (map_Pr), B = metallic (map_Pm).
    uint32_t metalRough(const std::filesystem::path& roughness, const std::filesystem::path& metallic) {
        return load(
            {roughness, metallic, "metalRough"},
            [&] {
                std::optional<Pixels> r = read(roughness), m = read(metallic);
                if (!r && !m) return std::optional<Pixels>();
                const Pixels& size = r ? *r : *m;
                Pixels out{size.width, size.height, std::vector<uint8_t>(size.rgba.size(), 255)};
                if (r) copyChannel(*r, 0, out, 1);
                if (m) copyChannel(*m, 0, out, 2);
                return std::optional<Pixels>(out);
            },
            VK_FORMAT_R8G8B8A8_UNORM, 0);
    }

private:
    using Key = std::tuple<std::filesystem::path, std::filesystem::path, std::string>;

    template <typename Make>
    uint32_t load(const Key& key, Make make, VkFormat format, uint32_t fallback) {
        if (std::get<0>(key).empty() && std::get<1>(key).empty()) return fallback;
        auto it = loaded_.find(key);
        if (it != loaded_.end()) return it->second;
        std::optional<Pixels> pixels = make();
        uint32_t index = fallback;
        if (pixels) {
            index = uint32_t(scene_.textures.size());
            scene_.textures.push_back(uploadTexture(device_, batch_, *pixels, format));
            bool alpha = false;
            for (size_t i = 3; i < pixels->rgba.size() && !alpha; i += 4) alpha = pixels->rgba[i] < 255;
            scene_.textureHasAlpha.push_back(alpha);
        }
        loaded_[key] = index;
        return index;
    }

    std::optional<Pixels> read(const std::filesystem::path& path) {
        if (path.empty()) return std::nullopt;
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            if (warned_.insert(path).second)
                std::fprintf(stderr, "warning: texture '%s' not found; using the default texture\n",
                             utf8(path).c_str());
            return std::nullopt;
        }
        return loadPixels(path, device_.properties.limits.maxImageDimension2D);
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
    StagingBatch& batch_;
    GpuScene& scene_;
    std::map<Key, uint32_t> loaded_;
    std::set<std::filesystem::path> warned_;
};

}  // namespace

GpuScene loadGpuScene(const Device& device, const Scene& scene, ModelCache& models, GpuSceneTextures wanted) {
    GpuScene gpu;
    StagingBatch batch = beginStaging(device);
    TextureLoader textures(device, batch, gpu);
    std::map<std::filesystem::path, uint32_t> firstMesh;       // per OBJ: its meshes' index in gpu.meshes
    std::map<std::filesystem::path, uint32_t> plainMaterials;  // per OBJ without overrides: its materials
    bool firstBounds = true;

    for (uint32_t instanceIndex = 0; instanceIndex < scene.models.size(); ++instanceIndex) {
        const ModelInstance& instance = scene.models[instanceIndex];
        const ModelData& model = loadObjModelCached(models, instance.file);
        if (!firstMesh.count(instance.file)) {
            firstMesh[instance.file] = uint32_t(gpu.meshes.size());
            for (const MeshData& mesh : model.meshes) {
                GpuMesh out;
                out.vertices =
                    uploadStaged(device, batch, mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex),
                                 VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
                out.indices =
                    uploadStaged(device, batch, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
                out.indexCount = uint32_t(mesh.indices.size());
                out.boundsMin = out.boundsMax = mesh.vertices.front().position;
                for (const Vertex& v : mesh.vertices) {
                    out.boundsMin = glm::min(out.boundsMin, v.position);
                    out.boundsMax = glm::max(out.boundsMax, v.position);
                }
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
        uint32_t materialBase = uint32_t(gpu.materials.size());
        if (instance.materials.empty() && plainMaterials.count(instance.file)) {
            materialBase = plainMaterials[instance.file];
        } else {
            if (instance.materials.empty()) plainMaterials[instance.file] = materialBase;
            for (const MaterialData& m : model.materials) {
                MaterialOverride o;
                if (auto it = instance.materials.find(m.name); it != instance.materials.end()) o = it->second;
                GpuMaterial material;
                material.diffuse = o.diffuse.value_or(m.diffuse);
                material.roughness = o.roughness.value_or(m.roughness);
                material.metallic = o.metallic.value_or(m.metallic);
                material.albedoTexture =
                    textures.albedo(o.diffuseTexture.value_or(m.diffuseTexture), m.alphaTexture);
                if (wanted.normalMaps)
                    material.normalTexture = textures.normal(o.normalTexture.value_or(m.normalTexture));
                if (wanted.metalRoughMaps)
                    material.metalRoughTexture = textures.metalRough(m.roughnessTexture, m.metallicTexture);
                material.alphaTested =
                    material.diffuse.a < 1.0f || gpu.textureHasAlpha[material.albedoTexture];
                gpu.materials.push_back(material);
            }
        }

        glm::mat4 matrix = instance.transform.matrix();
        for (size_t i = 0; i < model.meshes.size(); ++i) {
            gpu.draws.push_back(Draw{firstMesh[instance.file] + uint32_t(i),
                                     materialBase + model.meshes[i].material, matrix, instanceIndex});
            gpu.triangles += model.meshes[i].indices.size() / 3;
        }
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 local((corner & 1) ? model.boundsMax.x : model.boundsMin.x,
                            (corner & 2) ? model.boundsMax.y : model.boundsMin.y,
                            (corner & 4) ? model.boundsMax.z : model.boundsMin.z);
            glm::vec3 world = glm::vec3(matrix * glm::vec4(local, 1.0f));
            gpu.boundsMin = firstBounds ? world : glm::min(gpu.boundsMin, world);
            gpu.boundsMax = firstBounds ? world : glm::max(gpu.boundsMax, world);
            firstBounds = false;
        }
    }
    endStaging(device, batch);
    return gpu;
}

void destroyGpuScene(const Device& device, GpuScene& scene) {
    for (Image& texture : scene.textures) destroyImage(device, texture);
    for (GpuMesh& mesh : scene.meshes) {
        destroyBuffer(device, mesh.indices);
        destroyBuffer(device, mesh.vertices);
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

}  // namespace common
