// chapter-16: the cascades as the shadow pass's geometry shader and the light pass read them
// (std140). C++: CascadeUniform (chapter-16/shadow_pass.hpp).
#ifndef CASCADES_GLSL
#define CASCADES_GLSL

#define MAX_CASCADES 4  // kMaxCascades

struct Cascades {
    mat4 viewProjection[MAX_CASCADES];  // world -> each cascade's clip space
    vec4 splitFar;                      // where each cascade's slice ends (view distance)
    vec4 texelSize;                     // a texel's size in the world, per cascade
    mat4 cameraView;                    // world -> the camera's view
    int count;
    uint moving;                        // bit i: the moving casters' map holds casters of cascade i
    ivec4 layerOffset[MAX_CASCADES];    // xy: where each box's first texel lies in its layer
    vec4 toSun;                         // xyz: unit vector toward the sun, world space
    vec4 varianceFloor;                 // per cascade: the Chebyshev bound's least variance
};

#endif
