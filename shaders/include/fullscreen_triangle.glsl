// One triangle that covers the whole viewport, generated from gl_VertexIndex with no vertex
// buffer (the book's lighting vertex shader, chapter 10). Vertex 0, 1, 2 get texture coordinates
// (0,0), (2,0), (0,2) and clip positions (-1,1), (3,1), (-1,-3): the part inside the viewport has
// uv in [0,1]^2, with uv (0,0) at the top-left under our flipped viewport.
//> fullscreen
vec2 fullscreenUv(int vertexIndex) {
    return vec2((vertexIndex << 1) & 2, vertexIndex & 2);
}

vec4 fullscreenPosition(vec2 uv) {
    return vec4(uv.x * 2.0 - 1.0, uv.y * -2.0 + 1.0, 0.0, 1.0);
}
//< fullscreen
