// Work-group reduction of a brick's slotState word over its voxels: the state
// (solver_common.glsl's STATE_*) and the faces the band reaches (FACE_REACH_SHIFT). Each
// invocation ORs its voxels' bits (voxelState) and adds them to the group's once
// (noteBrickState): a shared atomic per voxel was a large part of a step on llvmpipe, which
// runs each lane's atomic in turn.
const uint VOXEL_LIVE = 1u;     // |phi| < PHI_FAR
const uint VOXEL_NEGATIVE = 2u; // clamped inside
const uint VOXEL_POSITIVE = 4u; // clamped outside
const uint VOXEL_FACES_SHIFT = 3u; // a live voxel's brick faces (facesOf)
shared uint stateBits;

void beginBrickState() {
    if (gl_LocalInvocationIndex == 0u) {
        stateBits = 0u;
    }
}

// The brick faces local voxel l lies on, one bit per face in FACE_NEIGHBOURS order.
uint facesOf(ivec3 l) {
    uvec3 low = uvec3(equal(l, ivec3(0)));
    uvec3 high = uvec3(equal(l, ivec3(BRICK_SIZE - 1)));
    return low.x | (high.x << 1) | (low.y << 2) | (high.y << 3) | (low.z << 4) | (high.z << 5);
}

// The bits of local voxel l (inside the volume) with this phi.
uint voxelState(ivec3 l, float phi) {
    if (abs(phi) < PHI_FAR) {
        return VOXEL_LIVE | (facesOf(l) << VOXEL_FACES_SHIFT);
    }
    return phi < 0.0 ? VOXEL_NEGATIVE : VOXEL_POSITIVE;
}

// An invocation's voxels' bits, OR-ed; call between beginBrickState's barrier and the next.
void noteBrickState(uint bits) {
    if (bits != 0u) {
        atomicOr(stateBits, bits);
    }
}

// Call after a barrier().
uint brickState() {
    if ((stateBits & VOXEL_LIVE) != 0u) {
        return STATE_LIVE | ((stateBits >> VOXEL_FACES_SHIFT) << FACE_REACH_SHIFT);
    }
    if ((stateBits & VOXEL_NEGATIVE) != 0u && (stateBits & VOXEL_POSITIVE) != 0u) {
        return STATE_MIXED;
    }
    return (stateBits & VOXEL_NEGATIVE) != 0u ? STATE_INSIDE : STATE_OUTSIDE;
}
