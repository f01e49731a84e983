// The level set's sparse storage, shared by the solver (which writes it) and the renderer
// (which draws the surface straight from it). Contract, mirrored on the host in
// app/solver/brick_pool_view.hpp:
// - the volume is cut into BRICK_SIZE^3 bricks; brick (bx, by, bz) has linear index
//   bx + brickGrid.x * (by + brickGrid.y * bz);
// - pageTable[brick] is a pool slot, or BRICK_INSIDE / BRICK_OUTSIDE for bricks whose phi is
//   the constant -PHI_FAR / +PHI_FAR (nothing stored);
// - phiPool[slot * BRICK_VOXELS + lx + BRICK_SIZE * (ly + BRICK_SIZE * lz)] is phi at local
//   voxel (lx, ly, lz) of that slot's brick;
// - phi < 0 inside the surface, > 0 outside, in voxel units, clamped to [-PHI_FAR, PHI_FAR].
// The host injects BRICK_SIZE and PHI_FAR with #define; the fallbacks keep build-time
// validation working.
#ifndef BRICK_SIZE
#define BRICK_SIZE 8
#endif
#ifndef PHI_FAR
#define PHI_FAR 4.0
#endif
#include "common/bindings.h"
// Readers leave these as they are; the solver's passes that allocate bricks define them empty
// (before including this file) to write the page table and the pool.
#ifndef PAGE_TABLE_ACCESS
#define PAGE_TABLE_ACCESS readonly
#endif
#ifndef PHI_POOL_ACCESS
#define PHI_POOL_ACCESS readonly
#endif

const uint BRICK_VOXELS = uint(BRICK_SIZE * BRICK_SIZE * BRICK_SIZE);
const uint BRICK_INSIDE = 0xFFFFFFFEu;
const uint BRICK_OUTSIDE = 0xFFFFFFFFu;

layout(std430, binding = PAGE_TABLE_BINDING) PAGE_TABLE_ACCESS buffer PageTable { uint pageTable[]; };
layout(std430, binding = PHI_POOL_BINDING) PHI_POOL_ACCESS buffer PhiPool { float phiPool[]; };

uniform ivec3 volumeDims; // voxels
uniform ivec3 brickGrid;  // bricks per axis = ceil(volumeDims / BRICK_SIZE)

uint brickIndex(ivec3 brick) {
    return uint(brick.x + brickGrid.x * (brick.y + brickGrid.y * brick.z));
}

// phi at a voxel; voxels outside the volume take the nearest border voxel's value.
float phiAt(ivec3 voxel) {
    ivec3 v = clamp(voxel, ivec3(0), volumeDims - 1);
    ivec3 brick = v / BRICK_SIZE;
    uint slot = pageTable[brickIndex(brick)];
    if (slot == BRICK_INSIDE) {
        return -PHI_FAR;
    }
    if (slot == BRICK_OUTSIDE) {
        return PHI_FAR;
    }
    ivec3 l = v - brick * BRICK_SIZE;
    return phiPool[slot * BRICK_VOXELS + uint(l.x + BRICK_SIZE * (l.y + BRICK_SIZE * l.z))];
}

// Trilinear phi at a continuous voxel-index position (voxel centres at integers). Continuous
// across brick borders because each corner is looked up through the page table on its own.
float phiTrilinear(vec3 p) {
    vec3 base = floor(p);
    vec3 f = p - base;
    ivec3 b = ivec3(base);
    float c000 = phiAt(b);
    float c100 = phiAt(b + ivec3(1, 0, 0));
    float c010 = phiAt(b + ivec3(0, 1, 0));
    float c110 = phiAt(b + ivec3(1, 1, 0));
    float c001 = phiAt(b + ivec3(0, 0, 1));
    float c101 = phiAt(b + ivec3(1, 0, 1));
    float c011 = phiAt(b + ivec3(0, 1, 1));
    float c111 = phiAt(b + ivec3(1, 1, 1));
    float x00 = mix(c000, c100, f.x);
    float x10 = mix(c010, c110, f.x);
    float x01 = mix(c001, c101, f.x);
    float x11 = mix(c011, c111, f.x);
    return mix(mix(x00, x10, f.y), mix(x01, x11, f.y), f.z);
}
