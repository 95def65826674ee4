#version 450
// chapter-10 geometry pass: writes the albedo of the nearest surface into the G-buffer.

//> geometry-frag
// One pipeline per material class the scene has (geometry_pass.cpp), fixed by two
// specialization constants: ALPHA_TEST, for cut-outs (opaque materials compile the test and its
// discard away, so the depth test can run before the shader), and BASE_COLOR_MAP, for materials
// with a texture (the others skip the sampling). The defaults are the generic pipeline's
// (--pipelines generic): right for any material.
layout(constant_id = 0) const bool ALPHA_TEST = true;
layout(constant_id = 1) const bool BASE_COLOR_MAP = true;

layout(location = 0) in vec2 inUv;

layout(location = 0) out vec4 outAlbedo;

layout(set = 2, binding = 0) uniform sampler2D albedoTexture;
layout(set = 3, binding = 0) uniform Material {
    vec4 diffuse;
    float alphaCutoff;  // 0 for opaque materials (C++: GeometryMaterial)
} material;

void main() {
    // MTL semantics: the texture is modulated by Kd (the book adds them instead).
    vec4 albedo = material.diffuse;
    if (BASE_COLOR_MAP) albedo *= texture(albedoTexture, inUv);
    // Alpha-tested cut-outs (the grille): a G-buffer holds one surface per pixel, so a
    // fragment is either kept whole or discarded.
    if (ALPHA_TEST && albedo.a < material.alphaCutoff) discard;
    outAlbedo = vec4(albedo.rgb, 1.0);
}
//< geometry-frag
