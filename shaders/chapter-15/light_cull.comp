#version 450
// Beyond the book, --light-culling tiled, passes 2 and 4: one invocation per light with a range.
// The light's sphere (its range) is projected to a rectangle of tiles; each tile of it whose box
// (light_cull_bounds.comp) the sphere reaches gets the light. The work is the tiles a light
// covers on screen, not lights x tiles. Compiled once, run twice: COUNT (FILL false) counts the
// lights of each tile; light_cull_scan.comp turns the counts into list offsets; FILL writes the
// light indices into the lists. Both passes make exactly the same decisions.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "light_cull.glsl"

//> cull-lights
layout(local_size_x = 64) in;
layout(constant_id = 0) const bool FILL = false;

layout(scalar, set = 1, binding = 0) readonly buffer Lights {
    ShaderLight lights[];
};
layout(scalar, set = 2, binding = 0) uniform Scene {
    ShaderSceneInfo scene;
};

void main() {
    uint i = scene.unboundedLightCount + gl_GlobalInvocationID.x;
    if (i >= scene.lightCount) return;
    ShaderLight light = lights[i];
    vec3 center = mat3(cull.viewRotation) * (light.position - scene.cameraPosition);
    // The range, widened by how far a stored surface position may lie from its pixel's ray and
    // by fp32 rounding, so that culling never drops a light the shading would see.
    float reach = light.range + cull.margin + 1.0e-5 * (length(center) + light.range);
    float z = -center.z;  // distance in front of the camera
    float zFar = z + reach;
    if (!(zFar >= cull.near)) return;  // wholly behind the near plane
    float zNear = max(z - reach, cull.near);

    // The sphere's screen rectangle: the largest and smallest x/z and y/z over the box around it
    // (clipped to the near plane). Conservative; exact enough for small, distant lights.
    vec2 lo = center.xy - reach, hi = center.xy + reach;
    vec2 slopeMax = vec2(hi.x > 0.0 ? hi.x / zNear : hi.x / zFar, hi.y > 0.0 ? hi.y / zNear : hi.y / zFar);
    vec2 slopeMin = vec2(lo.x < 0.0 ? lo.x / zNear : lo.x / zFar, lo.y < 0.0 ? lo.y / zNear : lo.y / zFar);
    vec2 ndcMin = slopeMin * cull.projectionScale, ndcMax = slopeMax * cull.projectionScale;
    if (any(greaterThan(ndcMin, vec2(1.0))) || any(lessThan(ndcMax, vec2(-1.0)))) return;  // off screen
    ndcMin = max(ndcMin, vec2(-1.0));
    ndcMax = min(ndcMax, vec2(1.0));
    // NDC to pixels: x right, y down (our viewport is flipped: NDC y is up).
    vec2 size = vec2(cull.extent);
    vec2 pixelMin = vec2((ndcMin.x + 1.0) * 0.5 * size.x, (1.0 - ndcMax.y) * 0.5 * size.y);
    vec2 pixelMax = vec2((ndcMax.x + 1.0) * 0.5 * size.x, (1.0 - ndcMin.y) * 0.5 * size.y);
    uvec2 first = uvec2(clamp(floor(pixelMin / float(LIGHT_TILE_SIZE)), vec2(0.0), vec2(cull.tileCount - 1u)));
    uvec2 last = uvec2(clamp(floor(pixelMax / float(LIGHT_TILE_SIZE)), vec2(0.0), vec2(cull.tileCount - 1u)));

    for (uint y = first.y; y <= last.y; ++y) {
        for (uint x = first.x; x <= last.x; ++x) {
            uint tile = y * cull.tileCount.x + x;
            vec4 boxMin = tileBounds[2u * tile];
            if (boxMin.w == 0.0) continue;  // no surface in this tile
            vec3 nearest = clamp(center, boxMin.xyz, tileBounds[2u * tile + 1u].xyz);
            vec3 away = center - nearest;
            if (dot(away, away) > reach * reach) continue;  // the sphere misses the tile's surfaces
            if (!FILL) {
                atomicAdd(tileCounts[tile], 1u);
            } else if (tileLists[tile].y != TILE_OVERFLOW) {
                uint slot = atomicAdd(tileLists[tile].y, 1u);
                tileLightIndices[tileLists[tile].x + slot] = i;
            }
        }
    }
}
//< cull-lights
