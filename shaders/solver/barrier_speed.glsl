// Barriers: spheres the operator fixed on one side of the surface for the rest of the run
// (model::Barrier). A blocking one (radius w > 0: a leak's neck, an erase that sticks) makes the
// speed negative whatever the scan says; a keeping one (w < 0: an added correction) makes it
// positive. Either way at least barrierHold, which the host sets so that alpha * hold outweighs
// the curvature term's pull: the front recedes from a blocking sphere and never crosses it, and
// never leaves a keeping one. Where spheres overlap, the newest decides (the operator's latest
// word). A keeping sphere may carry its tissue's level L (model::TissueLevel): within its reach,
// outside every sphere, the threshold and edge speeds also admit what lies between T and L,
// eps beyond each (speed/data_speed.glsl windowSpeed): the structure the operator extended and
// the partial volume between it and the added tissue. The classify speed learns the sphere
// instead; bounded by the window (classifyWithinWindow), its bound widens there as the
// threshold's does. Outside the operator's box (model::Box; without one it holds the whole scan)
// every voxel blocks as a blocking sphere does: the surface never leaves the box. So does every
// voxel another structure holds (LevelSetSolver::setClaimed): the surface never enters it. A
// kept voxel (LevelSetSolver::setKept) keeps as a keeping sphere does: the surface never
// leaves it.
// The host side: LevelSetSolver::uploadBarriers (app/solver/level_set_edits.cpp).
// Include after speed/data_speed.glsl and solver/sphere_metric.glsl.
#ifndef MAX_BARRIERS
#define MAX_BARRIERS 16
#endif
uniform int barrierCount;
uniform vec4 barriers[MAX_BARRIERS]; // centre (voxel indices), signed radius (sphere_metric.glsl)
uniform vec2 barrierLevels[MAX_BARRIERS]; // tissue level (real units), reach (as a radius; 0: none)
uniform float barrierHold;
uniform ivec3 boxLo;
uniform ivec3 boxHi;
// One bit a voxel, 32 along i to a texel (bit i % 32 of texel (i / 32, j, k):
// solver/voxel_bits.hpp); each bound only while its flag is set, so a run without such voxels
// reads no texture here. Claimed: another structure's, blocking. Kept: the part of the surface an
// erase's run may not take back (the workflow's: docs/steering.md), keeping.
precision highp usampler3D;
layout(binding = SOLVER_CLAIMED_UNIT) uniform highp usampler3D claimedBits;
uniform bool hasClaimed;
layout(binding = SOLVER_KEPT_UNIT) uniform highp usampler3D keptBits;
uniform bool hasKept;

bool voxelBit(highp usampler3D bits, ivec3 voxel) {
    uint word = texelFetch(bits, ivec3(voxel.x >> 5, voxel.yz), 0).r;
    return ((word >> uint(voxel.x & 31)) & 1u) != 0u;
}

float barrierSpeed(ivec3 voxel, float dataSpeed) {
    if (any(lessThan(voxel, boxLo)) || any(greaterThan(voxel, boxHi)) ||
        (hasClaimed && voxelBit(claimedBits, voxel))) {
        return -max(abs(dataSpeed), barrierHold);
    }
    vec3 p = vec3(voxel);
    float speed = dataSpeed;
    for (int n = barrierCount - 1; n >= 0; --n) {
        float w = barriers[n].w;
        float d = sphereNorm(p - barriers[n].xyz);
        if (d <= abs(w)) {
            float held = max(abs(dataSpeed), barrierHold);
            return w < 0.0 ? held : -held;
        }
        float reach = barrierLevels[n].y;
        if ((speedKind != 2 || classifyWithinWindow != 0) && reach > 0.0 && d <= reach) {
            float level = barrierLevels[n].x; // the window [min(T, L) - eps, max(T, L) + eps]
            float halfWidth = eps + 0.5 * abs(level - T);
            float w = windowSpeed(voxel, 0.5 * (level + T), halfWidth);
            speed = max(speed, speedKind != 2 ? w
                                              : classifyWithin(texelFetch(speedFactor, voxel, 0).r,
                                                               w, halfWidth));
        }
    }
    // After the spheres: a tap's erase in the kept part, the operator's newer word, blocks.
    if (hasKept && voxelBit(keptBits, voxel)) {
        return max(abs(dataSpeed), barrierHold);
    }
    return speed;
}
