#version 310 es
// The box, in bricks, of every brick not stored as constant "outside" (the band and the inside
// bricks). Beyond it phi is +PHI_FAR wherever a trilinear cell reaches, so the ray caster's
// surface search (raycast.comp, firstCrossing) looks for the surface inside it only. One
// invocation per brick; each group reduces in shared memory, then one atomic per bound.
// The host fills bounds with (INT_MAX x3, -1 x3) first; max < min after the pass: no such brick.
layout(local_size_x = 64) in;

#include "common/brick_pool.glsl"

layout(std430, binding = VIEW_BAND_BOUNDS_BINDING) buffer BandBounds { int bounds[6]; };

shared int groupBounds[6];

void main() {
    uint local = gl_LocalInvocationIndex;
    if (local < 6u) {
        groupBounds[local] = local < 3u ? 0x7FFFFFFF : -1;
    }
    barrier();
    // Groups laid out in two dimensions so that a grid of more than 65535 * 64 bricks fits.
    uint index = gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * gl_NumWorkGroups.x * 64u;
    uint count = uint(brickGrid.x * brickGrid.y * brickGrid.z);
    if (index < count && pageTable[index] != BRICK_OUTSIDE) {
        int i = int(index);
        ivec3 b = ivec3(i % brickGrid.x, (i / brickGrid.x) % brickGrid.y,
                        i / (brickGrid.x * brickGrid.y));
        atomicMin(groupBounds[0], b.x);
        atomicMin(groupBounds[1], b.y);
        atomicMin(groupBounds[2], b.z);
        atomicMax(groupBounds[3], b.x);
        atomicMax(groupBounds[4], b.y);
        atomicMax(groupBounds[5], b.z);
    }
    barrier();
    if (local < 3u) {
        atomicMin(bounds[local], groupBounds[local]);
    } else if (local < 6u) {
        atomicMax(bounds[local], groupBounds[local]);
    }
}
