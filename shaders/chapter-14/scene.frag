#version 450
// chapter-14 scene pass: writes the G-buffer's colour attachments (albedo only, until chapter-15).

//> scene-frag
layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outAlbedo;  // colour attachment 0 of vkCmdBeginRendering

// All materials in one storage buffer, selected by the index the draw pushes.
struct Material {
    vec4 diffuse;
};
layout(set = 1, binding = 0) readonly buffer Materials {
    Material materials[];
};
layout(set = 2, binding = 0) uniform sampler2D albedoTexture;

layout(push_constant) uniform Draw {
    layout(offset = 64) uint materialIndex;  // bytes 64..67, fragment stage
} draw;

void main() {
    vec4 albedo = materials[draw.materialIndex].diffuse * texture(albedoTexture, inUv);
    if (albedo.a < 0.5) discard;
    outAlbedo = vec4(albedo.rgb, 1.0);
}
//< scene-frag
