// chapter-15 light pass, shared by its two forms: light.frag (a full-screen triangle, the book's)
// and light.comp (a compute dispatch, one invocation per pixel). Declares the G-buffer, lights and
// scene bindings and the push constants, and shadePixel(): the light pass's colour of one pixel.
// Compiled with COMPACT_GBUFFER for --gbuffer compact, which stores no position: it is
// reconstructed from the (reversed-Z) depth; albedo comes as sqrt(albedo) in 10 bits, roughness
// and metallic in 16. Compiled with TILED_LIGHTS for --light-culling tiled (beyond the book): the
// lights come from the pixel's tile list (light_tiles.glsl).
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

// What the G-buffer holds at `uv` (0..1 across the image, texel centres), decoded: the same for
// the light pass and (beyond the book) the tile bounds of --light-culling tiled.
// textureLod: the attachments have one level, and a compute shader has no implicit level.
struct SurfaceSample {
    bool surface;   // written 1 where a surface was drawn, cleared to 0
    vec3 position;  // relative to the camera
    vec3 albedo;
    vec3 normal;    // as stored
    vec3 pbr;       // AO, roughness, metallic
    float depth;
};

SurfaceSample readGBuffer(vec2 uv) {
    SurfaceSample s;
    s.depth = textureLod(depthAttachment, uv, 0.0).r;
    vec4 albedoCoverage = textureLod(albedoAttachment, uv, 0.0);
    s.surface = albedoCoverage.a > 0.5;
#ifdef COMPACT_GBUFFER
    s.albedo = albedoCoverage.rgb * albedoCoverage.rgb;  // stored as sqrt(albedo)
    s.pbr = vec3(1.0, textureLod(pbrAttachment, uv, 0.0).rg);  // AO (not stored: none), roughness, metallic
    s.normal = decodeOctahedral(textureLod(normalAttachment, uv, 0.0).xy);
    // The pixel's clip-space point (y up under our flipped viewport) back to camera-relative space.
    vec4 clip = vec4(uv.x * 2.0 - 1.0, 1.0 - uv.y * 2.0, s.depth, 1.0);
    vec4 relative = show.clipToCameraRelative * clip;
    s.position = relative.xyz / relative.w;
#else
    s.albedo = albedoCoverage.rgb;
    s.pbr = textureLod(pbrAttachment, uv, 0.0).rgb;
    s.normal = textureLod(normalAttachment, uv, 0.0).xyz;
    s.position = textureLod(positionAttachment, uv, 0.0).xyz - scene.cameraPosition;
#endif
    return s;
}

// Light i's contribution to a surface point (camera-relative position, unit N and V).
vec3 shadeLight(uint i, SurfaceSample s, vec3 N, vec3 V) {
    ShaderLight light = lights[i];
    bool directional = light.directional != 0u;
    vec3 lightPosition = directional ? light.position : light.position - scene.cameraPosition;
    return evaluateLightInRange(directional, lightPosition, light.color, light.intensity, light.range, s.position, N,
                                V, s.albedo, s.pbr.b, s.pbr.g);
}

#ifdef TILED_LIGHTS
#include "light_tiles.glsl"
#endif

// The pixel at `uv` (texel centres; `pixel` its integer coordinates): lit, or the attachment --view
// asks for.
vec4 shadePixel(vec2 uv, ivec2 pixel) {
    SurfaceSample s = readGBuffer(uv);
    if (show.view == 1) {
        vec3 world = s.position + scene.cameraPosition;
        return vec4(s.surface ? clamp((world - show.boundsMin.xyz) / (show.boundsMax.xyz - show.boundsMin.xyz), 0.0, 1.0)
                              : vec3(0.0), 1.0);
    } else if (show.view == 2) {
        return vec4(s.albedo, 1.0);
    } else if (show.view == 3) {
        return vec4(s.surface ? s.normal * 0.5 + 0.5 : vec3(0.0), 1.0);
    } else if (show.view == 4) {
        return vec4(s.pbr, 1.0);
    } else if (show.view == 5) {
        float distance = show.reversedZ != 0 ? eyeDistance(s.depth, show.far, show.near)
                                             : eyeDistance(s.depth, show.near, show.far);
        return vec4(vec3(distanceToGrey(distance, show.near, show.far)), 1.0);
    } else if (!s.surface) {
        return vec4(0.0, 0.0, 0.0, 1.0);  // nothing was drawn here: no surface to light
    } else {
        vec3 N = surfaceNormal(s.normal);
        vec3 V = viewDirection(s.position, vec3(0.0), N);  // the camera is the origin here
        // Ambient light, darkened by the surface's occlusion (glTF applies occlusion maps to
        // indirect light only: the lights below are not).
        vec3 color = scene.ambientColor * scene.ambientIntensity * s.albedo * s.pbr.r;
#ifdef TILED_LIGHTS
        color += shadeTileLights(pixel, s, N, V);  // beyond the book: light_tiles.glsl
#else
        for (uint i = 0u; i < scene.lightCount; ++i) color += shadeLight(i, s, N, V);
#endif
        return vec4(color, 1.0);
    }
}
//< light-shading
