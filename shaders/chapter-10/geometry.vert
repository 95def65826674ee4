#version 450
// chapter-10 geometry pass: transforms the scene's vertices; the texture coordinates go on to
// the fragment shader.

//> geometry-vert
layout(location = 0) in vec3 inPosition;
layout(location = 4) in vec2 inUv;

layout(location = 0) out vec2 outUv;

layout(set = 0, binding = 0) uniform Projection { mat4 projection; };
layout(set = 1, binding = 0) uniform View { mat4 view; };
layout(push_constant) uniform Model { mat4 model; };

void main() {
    gl_Position = projection * view * model * vec4(inPosition, 1.0);
    outUv = inUv;
}
//< geometry-vert
