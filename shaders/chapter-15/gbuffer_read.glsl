// chapter-15 light pass: the book's G-buffer (set 0) and readGBuffer(), which decodes one pixel
// of it. Needs light_inputs.glsl first.

//> gbuffer-read
layout(set = 0, binding = 0) uniform sampler2D positionAttachment;
layout(set = 0, binding = 1) uniform sampler2D albedoAttachment;
layout(set = 0, binding = 2) uniform sampler2D normalAttachment;
layout(set = 0, binding = 3) uniform sampler2D pbrAttachment;
layout(set = 0, binding = 4) uniform sampler2D depthAttachment;

// `uv`: 0..1 across the image, texel centres. textureLod: the attachments have one level (and a
// compute shader would have no implicit level).
SurfaceSample readGBuffer(vec2 uv) {
    SurfaceSample s;
    s.depth = textureLod(depthAttachment, uv, 0.0).r;
    vec4 albedoCoverage = textureLod(albedoAttachment, uv, 0.0);
    s.surface = albedoCoverage.a > 0.5;
    s.albedo = albedoCoverage.rgb;
    s.pbr = textureLod(pbrAttachment, uv, 0.0).rgb;
    s.normal = textureLod(normalAttachment, uv, 0.0).xyz;
    s.position = textureLod(positionAttachment, uv, 0.0).xyz - scene.cameraPosition;
    return s;
}
//< gbuffer-read
