#version 450
// chapter-14 scene pass: writes the G-buffer's colour attachments (albedo only, until chapter-15).

//> scene-frag
// One pipeline per material class the scene has (scene_pass.cpp), fixed by two specialization
// constants: ALPHA_TEST, for cut-outs (opaque materials compile the test and its discard away,
// so the depth test can run before the shader), and BASE_COLOR_MAP, for materials with a texture
// (the others skip the sampling). The defaults are the generic pipeline's (--pipelines generic):
// right for any material.
layout(constant_id = 0) const bool ALPHA_TEST = true;
layout(constant_id = 1) const bool BASE_COLOR_MAP = true;

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outAlbedo;  // colour attachment 0 of vkCmdBeginRendering

// All materials in one storage buffer, selected by the index the draw pushes (C++: SceneMaterial).
struct Material {
    vec4 diffuse;
    float alphaCutoff;  // cut-outs: alpha below it is discarded (0 for opaque materials)
};
layout(set = 1, binding = 0) readonly buffer Materials {
    Material materials[];
};
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;

layout(push_constant) uniform Draw {
    layout(offset = 64) uint materialIndex;  // bytes 64..67, fragment stage
} draw;

void main() {
    Material material = materials[draw.materialIndex];
    vec4 albedo = material.diffuse;
    if (BASE_COLOR_MAP) albedo *= texture(albedoTexture, inUv);
    if (ALPHA_TEST && albedo.a < material.alphaCutoff) discard;
    outAlbedo = vec4(albedo.rgb, 1.0);
}
//< scene-frag
