#version 450
// chapter-06: positions pass straight through; the triangle is already in clip space.

//> main
layout(location = 0) in vec3 inPosition;

void main() {
    gl_Position = vec4(inPosition, 1.0);
}
//< main
