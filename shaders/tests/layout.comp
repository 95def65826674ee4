#version 450
// The layout test: reads the structs of gpu_types.glsl from buffers C++ filled and writes every
// field, in declaration order, as a float. tests/chapters/layout_test.cpp compares them with the values it
// wrote through the C++ twins (chapter-15/gpu_types.hpp, chapter-15-lab/light_culling.hpp).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "gpu_types.glsl"
#include "../chapter-15-lab/cull_view.glsl"

layout(local_size_x = 1) in;

layout(scalar, set = 0, binding = 0) readonly buffer Lights { ShaderLight lights[2]; };
layout(scalar, set = 0, binding = 1) uniform Scene { ShaderSceneInfo scene; };
layout(std430, set = 0, binding = 2) readonly buffer Materials { ShaderMaterial materials[2]; };
layout(std140, set = 0, binding = 3) uniform Camera { CameraUniform camera; };
layout(std430, set = 0, binding = 4) readonly buffer Draws { DrawConstants draw; };
layout(std430, set = 0, binding = 5) writeonly buffer Fields { float fields[]; };
layout(scalar, set = 0, binding = 6) uniform Cull { CullView cull; };
// As the light pass receives it: push constants (std430, as push constant blocks are by default).
layout(push_constant) uniform LightViewBlock { LightView show; };

void main() {
    int i = 0;
    for (int l = 0; l < 2; ++l) {
        fields[i++] = lights[l].position.x;
        fields[i++] = lights[l].position.y;
        fields[i++] = lights[l].position.z;
        fields[i++] = float(lights[l].directional);
        fields[i++] = lights[l].intensity;
        fields[i++] = lights[l].color.x;
        fields[i++] = lights[l].color.y;
        fields[i++] = lights[l].color.z;
        fields[i++] = lights[l].range;
    }
    fields[i++] = scene.cameraPosition.x;
    fields[i++] = scene.cameraPosition.y;
    fields[i++] = scene.cameraPosition.z;
    fields[i++] = scene.ambientIntensity;
    fields[i++] = scene.ambientColor.x;
    fields[i++] = scene.ambientColor.y;
    fields[i++] = scene.ambientColor.z;
    fields[i++] = float(scene.lightCount);
    for (int m = 0; m < 2; ++m) {
        fields[i++] = materials[m].diffuse.x;
        fields[i++] = materials[m].diffuse.y;
        fields[i++] = materials[m].diffuse.z;
        fields[i++] = materials[m].diffuse.w;
        fields[i++] = materials[m].roughness;
        fields[i++] = materials[m].metallic;
        fields[i++] = float(materials[m].flags);
        fields[i++] = materials[m].alphaCutoff;
        fields[i++] = materials[m].normalScale;
        fields[i++] = materials[m].occlusionStrength;
    }
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) fields[i++] = camera.projection[c][r];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) fields[i++] = camera.view[c][r];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) fields[i++] = draw.model[c][r];
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) fields[i++] = draw.normalMatrix[c][r];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) fields[i++] = show.clipToCameraRelative[c][r];
    for (int k = 0; k < 4; ++k) fields[i++] = show.boundsMin[k];
    for (int k = 0; k < 4; ++k) fields[i++] = show.boundsMax[k];
    fields[i++] = float(show.view);
    fields[i++] = show.near;
    fields[i++] = show.far;
    fields[i++] = float(show.reversedZ);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) fields[i++] = cull.viewRotation[c][r];
    fields[i++] = cull.projectionScale.x;
    fields[i++] = cull.projectionScale.y;
    fields[i++] = cull.near;
    fields[i++] = cull.margin;
    fields[i++] = float(cull.tileCount.x);
    fields[i++] = float(cull.tileCount.y);
    fields[i++] = float(cull.extent.x);
    fields[i++] = float(cull.extent.y);
    fields[i++] = float(cull.capacity);
    fields[i++] = float(cull.unboundedLights);
}
