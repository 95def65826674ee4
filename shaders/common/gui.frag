#version 450
// The GUI pass: the vertex colour times the font atlas (white glyphs with coverage in alpha; one
// white texel for everything that is not text).
//> gui-frag
layout(set = 0, binding = 0) uniform sampler2D fontAtlas;

layout(location = 0) in vec2 inUv;
layout(location = 1) in vec4 inColor;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = inColor * texture(fontAtlas, inUv);
}
//< gui-frag
