#version 450
// chapter-06: every fragment of the triangle is red.

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(1.0, 0.0, 0.0, 1.0);
}
