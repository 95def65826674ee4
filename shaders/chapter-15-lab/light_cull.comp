#version 450
// chapter-15-lab, --light-culling tiled, passes 2 and 4: lights to tiles. A light's sphere (its
// range) is projected to a rectangle of tiles; each tile of it whose box (light_cull_bounds.comp)
// the sphere reaches gets the light. The work is the tiles each light covers on screen, not
// lights x tiles. One module, four pipelines (specialization constants):
//   FILL false: count the lights of each tile; light_cull_scan.comp turns counts into offsets;
//   FILL true:  write the light indices into the lists -- the same decisions, so the same counts.
//   LARGE false: one invocation per light. A light whose rectangle has more than
//                LARGE_LIGHT_TILES tiles is left to LARGE true (the count pass lists it), so that
//                no invocation loops over thousands of tiles while the rest of the GPU waits;
//   LARGE true:  one group per listed light (an indirect dispatch), its 64 invocations sharing
//                the rectangle's tiles.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "light_cull.glsl"

//> cull-lights
layout(local_size_x = 64) in;
layout(constant_id = 0) const bool FILL = false;
layout(constant_id = 1) const bool LARGE = false;
const uint LARGE_LIGHT_TILES = 32u;

layout(scalar, set = 1, binding = 0) readonly buffer Lights {
    ShaderLight lights[];
};
layout(scalar, set = 2, binding = 0) uniform Scene {
    ShaderSceneInfo scene;
};

// Light i's sphere in view space and its rectangle of tiles; false when it is off screen.
bool lightRectangle(uint i, out vec3 center, out float reach, out uvec2 first, out uvec2 last) {
    ShaderLight light = lights[i];
    center = mat3(cull.viewRotation) * (light.position - scene.cameraPosition);
    // The range, widened by how far a stored surface position may lie from its pixel's ray and
    // by fp32 rounding, so that culling never drops a light the shading would see.
    reach = light.range + cull.margin + 1.0e-5 * (length(center) + light.range);
    float z = -center.z;  // distance in front of the camera
    float zFar = z + reach;
    if (!(zFar >= cull.near)) return false;  // wholly behind the near plane
    float zNear = max(z - reach, cull.near);
    // The sphere's screen rectangle: the largest and smallest x/z and y/z over the box around it
    // (clipped to the near plane). Conservative; exact enough for small, distant lights.
    vec2 lo = center.xy - reach, hi = center.xy + reach;
    vec2 slopeMax = vec2(hi.x > 0.0 ? hi.x / zNear : hi.x / zFar, hi.y > 0.0 ? hi.y / zNear : hi.y / zFar);
    vec2 slopeMin = vec2(lo.x < 0.0 ? lo.x / zNear : lo.x / zFar, lo.y < 0.0 ? lo.y / zNear : lo.y / zFar);
    vec2 ndcMin = slopeMin * cull.projectionScale, ndcMax = slopeMax * cull.projectionScale;
    if (any(greaterThan(ndcMin, vec2(1.0))) || any(lessThan(ndcMax, vec2(-1.0)))) return false;  // off screen
    ndcMin = max(ndcMin, vec2(-1.0));
    ndcMax = min(ndcMax, vec2(1.0));
    // NDC to pixels: x right, y down (our viewport is flipped: NDC y is up).
    vec2 size = vec2(cull.extent);
    vec2 pixelMin = vec2((ndcMin.x + 1.0) * 0.5 * size.x, (1.0 - ndcMax.y) * 0.5 * size.y);
    vec2 pixelMax = vec2((ndcMax.x + 1.0) * 0.5 * size.x, (1.0 - ndcMin.y) * 0.5 * size.y);
    first = uvec2(clamp(floor(pixelMin / float(LIGHT_TILE_SIZE)), vec2(0.0), vec2(cull.tileCount - 1u)));
    last = uvec2(clamp(floor(pixelMax / float(LIGHT_TILE_SIZE)), vec2(0.0), vec2(cull.tileCount - 1u)));
    return true;
}

// Light i and one tile of its rectangle: counted or listed when its sphere reaches the tile's box.
void visitTile(uint i, uvec2 xy, vec3 center, float reach) {
    uint tile = xy.y * cull.tileCount.x + xy.x;
    vec4 boxMin = tileBounds[2u * tile];
    if (boxMin.w == 0.0) return;  // no surface in this tile
    vec3 nearest = clamp(center, boxMin.xyz, tileBounds[2u * tile + 1u].xyz);
    vec3 away = center - nearest;
    if (dot(away, away) > reach * reach) return;  // the sphere misses the tile's surfaces
    if (!FILL) {
        atomicAdd(tileCounts[tile], 1u);
    } else if (tileLists[tile].y != TILE_OVERFLOW) {
        uint slot = atomicAdd(tileLists[tile].y, 1u);
        tileLightIndices[tileLists[tile].x + slot] = i;
    }
}

void main() {
    vec3 center;
    float reach;
    uvec2 first, last;
    if (LARGE) {  // one group per large light
        uint i = largeLights[gl_WorkGroupID.x];
        if (!lightRectangle(i, center, reach, first, last)) return;
        uint width = last.x - first.x + 1u, tiles = width * (last.y - first.y + 1u);
        for (uint k = gl_LocalInvocationID.x; k < tiles; k += gl_WorkGroupSize.x)
            visitTile(i, first + uvec2(k % width, k / width), center, reach);
        return;
    }
    uint i = cull.unboundedLights + gl_GlobalInvocationID.x;
    if (i >= scene.lightCount || !lightRectangle(i, center, reach, first, last)) return;
    if ((last.x - first.x + 1u) * (last.y - first.y + 1u) > LARGE_LIGHT_TILES) {
        if (!FILL) largeLights[atomicAdd(largeDispatch.x, 1u)] = i;  // the LARGE pass takes it
        return;
    }
    for (uint y = first.y; y <= last.y; ++y)
        for (uint x = first.x; x <= last.x; ++x) visitTile(i, uvec2(x, y), center, reach);
}
//< cull-lights
