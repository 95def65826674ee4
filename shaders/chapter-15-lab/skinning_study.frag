#version 450
// chapter-15-lab: the skinning study's scene pass writes the normal (the cascades write depth alone).
layout(location = 0) in vec3 inNormal;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(normalize(inNormal) * 0.5 + 0.5, 1.0);
}
