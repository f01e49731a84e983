// Work-group reduction of a brick's state (solver_common.glsl's STATE_*) over its voxels.
shared uint stateLive;
shared uint stateNegative;
shared uint statePositive;

void beginBrickState() {
    if (gl_LocalInvocationIndex == 0u) {
        stateLive = 0u;
        stateNegative = 0u;
        statePositive = 0u;
    }
}

void noteVoxelState(float phi) {
    if (abs(phi) < PHI_FAR) {
        atomicOr(stateLive, 1u);
    } else if (phi < 0.0) {
        atomicOr(stateNegative, 1u);
    } else {
        atomicOr(statePositive, 1u);
    }
}

// Call after a barrier().
uint brickState() {
    if (stateLive != 0u) {
        return STATE_LIVE;
    }
    if (stateNegative != 0u && statePositive != 0u) {
        return STATE_MIXED;
    }
    return stateNegative != 0u ? STATE_INSIDE : STATE_OUTSIDE;
}
