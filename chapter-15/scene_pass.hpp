// chapter-15: the scene pass -- the scene into the book's PBR G-buffer: world position, albedo,
// normal (with normal maps) and PBR data (AO, roughness, metallic), all R16G16B16A16_SFLOAT,
// plus D32_SFLOAT depth: 36 bytes per pixel (gbuffer_layout.hpp). The book's ScnRender and
// MrtAttachments. The G-buffer's barriers and vkCmdBeginRendering are chapter-14's, from
// common/passes/gbuffer.cpp.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "common/passes/camera_frames.hpp"
#include "common/passes/gbuffer.hpp"
#include "common/scene/camera.hpp"
#include "common/scene/gpu_scene.hpp"
#include "common/shaders/shader_watch.hpp"
#include "common/vk/buffer.hpp"
#include "common/vk/device.hpp"
#include "common/vk/pipeline.hpp"
#include "gbuffer_layout.hpp"
#include "gpu_types.hpp"

struct MeshDrawing;
// Chapter-15's way to draw one of the scene's draws, its pipeline and sets bound: the mesh's vertex
// and index buffers bound (the pipeline's vertex input reads them), the model and normal matrices
// and the material pushed, vkCmdDrawIndexed. `firstInstance` reaches the vertex shader as
// gl_InstanceIndex (chapter-16's shadow pass sends the cascades a draw goes to so).
void recordBoundMesh(VkCommandBuffer cmd, VkPipelineLayout layout, const MeshDrawing& drawing,
                     const common::GpuScene& scene, const common::Draw& draw, uint32_t firstInstance);

// How a draw's mesh and constants reach the shaders, for the scene pass and chapter-16's shadow
// pass alike: chapter-15's by default; chapter-18's vertex shaders read the buffers themselves
// through the addresses the draw pushes (chapter-18/mesh_pulling.hpp).
struct MeshDrawing {
    bool vertexInput = true;                           // the pipelines' vertex input state reads the mesh
    uint32_t vertexConstants = sizeof(DrawConstants);  // push constant bytes of the vertex stage, from 0
    uint32_t materialOffset = kDrawMaterialOffset;     // the fragment stage's material index (4 bytes)
    decltype(&recordBoundMesh) record = recordBoundMesh;
};

// The compiled shaders of a scene pipeline, files under <build>/bin/shaders/: the book's by
// default. A fragment shader starts from scene_surface.glsl's sceneSurface().
struct SceneShaders {
    std::string vertex = "chapter-15/scene.vert";
    std::string fragment = "chapter-15/scene.frag";
};

// What a scene pipeline draws into, and with which shaders.
struct ScenePipelineTarget {
    SceneShaders shaders;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
    bool reversedZ = false;
    std::vector<VkDescriptorSetLayout> moreSets;  // sets 3.. after the scene pass's own
    bool vertexInput = true;                      // the scene pass's MeshDrawing's (set when made)
};

// A material class: the features of a material that a scene pipeline is specialised for
// (scene_surface.glsl's constants). Materials of one class draw with one pipeline.
struct MaterialClass {
    uint32_t features = 0;   // the MATERIAL_ bits (gpu_types.hpp)
    bool alphaTest = false;  // a cut-out: alpha below its cutoff is discarded
    bool operator==(const MaterialClass&) const = default;
};

// The scene's pipelines from one fragment shader: one per material class the scene's materials
// have (none for classes no material has), each with back faces culled unless the class is
// double-sided (glTF's doubleSided). Generic ones (--pipelines generic) ask each material's
// features as they run: one per alpha test and sidedness the scene has.
struct ScenePipelines {
    VkPipelineLayout layout = VK_NULL_HANDLE;  // sets 0-2 (camera, materials, textures), then any more
    common::MaterialClasses<MaterialClass> materialClasses;  // the classes, and each material's
    std::vector<VkPipeline> pipelines;                       // one per class
    bool generic = false;                                    // FEATURES_AT_RUN_TIME
    ScenePipelineTarget target;  // what they were made for, to make them again on a reload
};

struct ScenePass {
    const GBufferLayout* layout = &kBookGBuffer;
    common::GBufferFormats formats;  // the layout's, with the depth format this device renders to
    common::GBuffer gbuffer;
    VkDescriptorSetLayout cameraLayout = VK_NULL_HANDLE;     // set 0: projection + view, per frame
    VkDescriptorSetLayout materialsLayout = VK_NULL_HANDLE;  // set 1: all materials, storage buffer
    VkDescriptorSetLayout texturesLayout = VK_NULL_HANDLE;   // set 2: one per material, its 4 textures
    VkDescriptorPool descriptorPool = VK_NULL_HANDLE;
    std::vector<common::CameraFrame> cameras;  // per frame in flight
    common::Buffer materials;
    VkDescriptorSet materialsSet = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> materialTextureSets;
    std::vector<MaterialClass> classOfMaterial;  // per material: the features it uses
    std::vector<bool> materialUsed;              // per material: whether a draw uses it
    bool genericPipelines = false;               // --pipelines generic
    MeshDrawing drawing;                         // how its draws (and the shadow pass's) reach the shaders
    ScenePipelines pipelines;
    std::vector<uint32_t> order;  // the draws' indices in the order they are recorded
    glm::vec3 orderedFrom{0.0f};  // the camera position `order` was made for
};

// The G-buffer of `layout` and the pipelines that fill it (none for a layout of depth alone).
// Throws Failure when the device cannot render to the layout's formats (for depth: to D32_SFLOAT
// or X8_D24_UNORM_PACK32, or to D32_SFLOAT for a reversed-Z layout).
ScenePass createScenePass(const common::Device& device, VkPipelineCache cache, VkExtent2D extent,
                          const common::GpuScene& scene, uint32_t framesInFlight,
                          const GBufferLayout& layout = kBookGBuffer, const SceneShaders& shaders = {},
                          bool genericPipelines = false, const MeshDrawing& drawing = {});
void resizeScenePass(const common::Device& device, ScenePass& pass, VkExtent2D extent);
void setCamera(ScenePass& pass, uint32_t frame, const glm::mat4& projection, const glm::mat4& view);
// What records the scene's draws inside the pass's rendering (sets 0 and 1 bound): chapter-15's
// recordSceneDraws by default; chapter-19 draws indirectly.
using SceneDrawsRecorder = std::function<void(VkCommandBuffer cmd)>;
// Opaque draws nearest first (so hidden fragments fail the depth test before shading), then cut-outs.
void recordScenePass(VkCommandBuffer cmd, ScenePass& pass, const common::GpuScene& scene, uint32_t frame,
                     glm::vec3 cameraPosition, const SceneDrawsRecorder& draws = {});
void destroyScenePass(const common::Device& device, ScenePass& pass);

// The scene pass's pipelines for a target and shaders (createScenePass makes the G-buffer's), and
// the scene's draws recorded with them (sets 0 and 1, and any more, bound by the caller).
ScenePipelines createScenePipelines(const common::Device& device, VkPipelineCache cache,
                                    const ScenePass& pass, const ScenePipelineTarget& target);
void recordSceneDraws(VkCommandBuffer cmd, ScenePass& pass, const ScenePipelines& pipelines,
                      const common::GpuScene& scene, glm::vec3 cameraPosition);
void destroyScenePipelines(const common::Device& device, ScenePipelines& pipelines);
// Live reload: new pipelines into `swap` when the reload changed their shaders.
void remakeScenePipelines(const common::Device& device, VkPipelineCache cache, ScenePipelines& pipelines,
                          const common::ShaderReload& reload, common::PipelineSwap& swap);
