#version 450
// chapter-15-lab, --light-culling tiled, pass 3: the tiles' counts to list offsets (an exclusive
// prefix sum, in one group of 256 invocations, each summing a run of tiles), so every tile's list
// is exactly as long as its count. A tile whose list would end past cull.capacity is marked
// TILE_OVERFLOW: the light pass then loops over every light there, so nothing is ever dropped.
// Also the frame's statistics (CullStats).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#include "light_cull.glsl"

//> cull-scan
layout(local_size_x = 256) in;

shared uint runTotals[256];

void main() {
    uint id = gl_LocalInvocationID.x;
    uint tiles = cull.tileCount.x * cull.tileCount.y;
    uint perInvocation = (tiles + 255u) / 256u;
    uint begin = min(id * perInvocation, tiles), end = min(begin + perInvocation, tiles);
    uint run = 0u;
    for (uint t = begin; t < end; ++t) run += tileCounts[t];
    runTotals[id] = run;
    barrier();
    for (uint step = 1u; step < 256u; step *= 2u) {  // inclusive scan of the runs (Hillis-Steele)
        uint before = id >= step ? runTotals[id - step] : 0u;
        barrier();
        runTotals[id] += before;
        barrier();
    }
    uint offset = runTotals[id] - run;
    uint longest = 0u, overflow = 0u, lit = 0u;
    for (uint t = begin; t < end; ++t) {
        uint count = tileCounts[t];
        bool fits = offset + count <= cull.capacity;
        tileLists[t] = uvec2(offset, fits ? 0u : TILE_OVERFLOW);  // the fill pass counts up to `count`
        offset += count;
        longest = max(longest, count);
        overflow += fits ? 0u : 1u;
        lit += count > 0u ? 1u : 0u;
    }
    if (id == 255u) pairs = runTotals[255];
    atomicMax(maxTileLights, longest);
    atomicAdd(overflowTiles, overflow);
    atomicAdd(litTiles, lit);
}
//< cull-scan
