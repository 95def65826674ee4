#version 450
// chapter-14 scene pass: as chapter-10's geometry pass, with the camera's two matrices in one
// uniform buffer per frame in flight.

//> scene-vert
layout(location = 0) in vec3 inPosition;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec2 outUv;

layout(set = 0, binding = 0) uniform CameraUniform {
    mat4 projection;
    mat4 view;
} camera;

layout(push_constant) uniform Draw {
    mat4 model;  // bytes 0..63, vertex stage
} draw;

void main() {
    gl_Position = camera.projection * camera.view * draw.model * vec4(inPosition, 1.0);
    outUv = inUv;
}
//< scene-vert
