#version 310 es
// One group per active brick: copies the shell update_phi set aside into the pool, completing
// the in-place step (see solver/brick_shell.glsl).
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/brick_shell.glsl"
layout(local_size_x = LOCAL_SIZE) in;

void main() {
    uint n = activeListIndex();
    if (n == NO_BRICK) {
        return;
    }
    uint slot = activeList[n];
    for (uint i = gl_LocalInvocationIndex; i < SHELL_VOXELS; i += uint(LOCAL_SIZE)) {
        ivec3 l = shellVoxel(i);
        uint v = uint(l.x + BRICK_SIZE * (l.y + BRICK_SIZE * l.z));
        phiPool[slot * BRICK_VOXELS + v] = shellNext[slot * SHELL_VOXELS + i];
    }
}
