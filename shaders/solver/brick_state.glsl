// Work-group reduction of a brick's slotState word over its voxels: the state
// (solver_common.glsl's STATE_*) and the faces the band reaches (FACE_REACH_SHIFT).
shared uint stateLive;
shared uint stateNegative;
shared uint statePositive;
shared uint stateFaces;

void beginBrickState() {
    if (gl_LocalInvocationIndex == 0u) {
        stateLive = 0u;
        stateNegative = 0u;
        statePositive = 0u;
        stateFaces = 0u;
    }
}

// The brick faces local voxel l lies on, one bit per face in FACE_NEIGHBOURS order.
uint facesOf(ivec3 l) {
    uvec3 low = uvec3(equal(l, ivec3(0)));
    uvec3 high = uvec3(equal(l, ivec3(BRICK_SIZE - 1)));
    return low.x | (high.x << 1) | (low.y << 2) | (high.y << 3) | (low.z << 4) | (high.z << 5);
}

// phi of local voxel l (inside the volume).
void noteVoxelState(ivec3 l, float phi) {
    if (abs(phi) < PHI_FAR) {
        atomicOr(stateLive, 1u);
        uint faces = facesOf(l);
        if (faces != 0u) {
            atomicOr(stateFaces, faces);
        }
    } else if (phi < 0.0) {
        atomicOr(stateNegative, 1u);
    } else {
        atomicOr(statePositive, 1u);
    }
}

// Call after a barrier().
uint brickState() {
    if (stateLive != 0u) {
        return STATE_LIVE | (stateFaces << FACE_REACH_SHIFT);
    }
    if (stateNegative != 0u && statePositive != 0u) {
        return STATE_MIXED;
    }
    return stateNegative != 0u ? STATE_INSIDE : STATE_OUTSIDE;
}
