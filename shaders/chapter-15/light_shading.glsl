// chapter-15 light pass, shared by its two forms: light.frag (a full-screen triangle, the book's)
// and light.comp (a compute dispatch, one invocation per pixel). Declares the G-buffer, lights and
// scene bindings and the push constants, and shadePixel(): the light pass's colour of one pixel.
// Compiled with COMPACT_GBUFFER for --gbuffer compact, which stores no position: it is
// reconstructed from the (reversed-Z) depth; albedo comes as sqrt(albedo) in 10 bits, roughness
// and metallic in 16.
//
// Shading happens in coordinates relative to the camera: position - camera and light - camera
// are small numbers where it matters (near the camera), however far the scene is from the world
// origin. Subtracting two nearby fp32 values is exact, so nothing is lost on the way.
#include "depth_view.glsl"
#include "gpu_types.glsl"
#include "octahedral.glsl"
#include "pbr.glsl"

//> light-shading
#ifdef COMPACT_GBUFFER
layout(set = 0, binding = 0) uniform sampler2D albedoAttachment;  // sqrt(albedo), coverage
layout(set = 0, binding = 1) uniform sampler2D normalAttachment;  // octahedral
layout(set = 0, binding = 2) uniform sampler2D pbrAttachment;     // roughness, metallic
layout(set = 0, binding = 3) uniform sampler2D depthAttachment;   // reversed-Z
#else
layout(set = 0, binding = 0) uniform sampler2D positionAttachment;
layout(set = 0, binding = 1) uniform sampler2D albedoAttachment;
layout(set = 0, binding = 2) uniform sampler2D normalAttachment;
layout(set = 0, binding = 3) uniform sampler2D pbrAttachment;
layout(set = 0, binding = 4) uniform sampler2D depthAttachment;
#endif

layout(scalar, set = 1, binding = 0) readonly buffer Lights {
    ShaderLight lights[];
};
layout(scalar, set = 2, binding = 0) uniform Scene {
    ShaderSceneInfo scene;
};

layout(push_constant) uniform LightViewBlock {
    LightView show;  // gpu_types.glsl
};

// The pixel at `uv` (0..1 across the image, texel centres): lit, or the attachment --view asks for.
// textureLod: the attachments have one level, and a compute shader has no implicit level.
vec4 shadePixel(vec2 uv) {
    float depth = textureLod(depthAttachment, uv, 0.0).r;
    vec4 albedoCoverage = textureLod(albedoAttachment, uv, 0.0);
    bool surface = albedoCoverage.a > 0.5;  // written 1 where a surface was drawn, cleared to 0
#ifdef COMPACT_GBUFFER
    vec3 albedo = albedoCoverage.rgb * albedoCoverage.rgb;  // stored as sqrt(albedo)
    vec3 pbr = vec3(0.5, textureLod(pbrAttachment, uv, 0.0).rg);  // AO (fixed 0.5, not stored), roughness, metallic
#else
    vec3 albedo = albedoCoverage.rgb;
    vec3 pbr = textureLod(pbrAttachment, uv, 0.0).rgb;  // AO, roughness, metallic
#endif
#ifdef COMPACT_GBUFFER
    vec3 normal = decodeOctahedral(textureLod(normalAttachment, uv, 0.0).xy);
    // The pixel's clip-space point (y up under our flipped viewport) back to camera-relative space.
    vec4 clip = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, depth, 1.0);
    vec4 relative = show.clipToCameraRelative * clip;
    vec3 position = relative.xyz / relative.w;
#else
    vec3 normal = textureLod(normalAttachment, uv, 0.0).xyz;
    vec3 position = textureLod(positionAttachment, uv, 0.0).xyz - scene.cameraPosition;
#endif

    if (show.view == 1) {
        vec3 world = position + scene.cameraPosition;
        return vec4(surface ? clamp((world - show.boundsMin.xyz) / (show.boundsMax.xyz - show.boundsMin.xyz), 0.0, 1.0)
                                : vec3(0.0), 1.0);
    } else if (show.view == 2) {
        return vec4(albedo, 1.0);
    } else if (show.view == 3) {
        return vec4(surface ? normal * 0.5 + 0.5 : vec3(0.0), 1.0);
    } else if (show.view == 4) {
        return vec4(pbr, 1.0);
    } else if (show.view == 5) {
        float distance = show.reversedZ != 0 ? eyeDistance(depth, show.far, show.near) : eyeDistance(depth, show.near, show.far);
        return vec4(vec3(distanceToGrey(distance, show.near, show.far)), 1.0);
    } else if (!surface) {
        return vec4(0.0, 0.0, 0.0, 1.0);  // nothing was drawn here: no surface to light
    } else {
        vec3 N = surfaceNormal(normal);
        vec3 V = viewDirection(position, vec3(0.0), N);  // the camera is the origin here
        vec3 color = scene.ambientColor * scene.ambientIntensity * albedo;
        for (uint i = 0u; i < scene.lightCount; ++i) {
            ShaderLight light = lights[i];
            bool directional = light.directional != 0u;
            vec3 lightPosition = directional ? light.position : light.position - scene.cameraPosition;
            color += evaluateLight(directional, lightPosition, light.color, light.intensity, position, N, V, albedo,
                                   pbr.b, pbr.g);
        }
        return vec4(color, 1.0);
    }
}
//< light-shading
