#version 310 es
// One group per active brick: one step of phi (phi_stencil.glsl) from the brick and a one-voxel
// apron staged in shared memory; records the brick's new state and whether any voxel changed
// side (convergence). phi is stored once: the interior is updated in place, the shell goes to
// shellNext until commit_shells (solver/brick_shell.glsl).
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/speed_threshold.glsl"
#include "solver/phi_stencil.glsl"
#include "solver/brick_state.glsl"
#include "solver/phi_tile.glsl"
#include "solver/brick_shell.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;

shared uint changedSide;

float t(ivec3 l) { return tileAt(l); }

PhiStencil stencilAt(ivec3 l) {
    PhiStencil s;
    s.c = t(l);
    s.xm = t(l + ivec3(-1, 0, 0));
    s.xp = t(l + ivec3(1, 0, 0));
    s.ym = t(l + ivec3(0, -1, 0));
    s.yp = t(l + ivec3(0, 1, 0));
    s.zm = t(l + ivec3(0, 0, -1));
    s.zp = t(l + ivec3(0, 0, 1));
    s.xpyp = t(l + ivec3(1, 1, 0));
    s.xpym = t(l + ivec3(1, -1, 0));
    s.xmyp = t(l + ivec3(-1, 1, 0));
    s.xmym = t(l + ivec3(-1, -1, 0));
    s.xpzp = t(l + ivec3(1, 0, 1));
    s.xpzm = t(l + ivec3(1, 0, -1));
    s.xmzp = t(l + ivec3(-1, 0, 1));
    s.xmzm = t(l + ivec3(-1, 0, -1));
    s.ypzp = t(l + ivec3(0, 1, 1));
    s.ypzm = t(l + ivec3(0, 1, -1));
    s.ymzp = t(l + ivec3(0, -1, 1));
    s.ymzm = t(l + ivec3(0, -1, -1));
    return s;
}

void main() {
    uint n = activeListIndex();
    if (n == NO_BRICK) {
        return;
    }
    uint slot = activeList[n];
    ivec3 origin = brickCoord(slotBrick[slot]) * BRICK_SIZE;
    loadTile(origin);
    beginBrickState();
    if (gl_LocalInvocationIndex == 0u) {
        changedSide = 0u;
    }
    barrier();
    float dt = ctrl.dt;
    for (uint v = gl_LocalInvocationIndex; v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        ivec3 g = origin + l;
        PhiStencil s = stencilAt(l);
        float out_ = s.c;
        if (all(lessThan(g, volumeDims))) {
            if (dt > 0.0 && tileInNarrowBand(l)) {
                out_ = phiStep(s, dataSpeed(g), alpha, dt);
            }
            noteVoxelState(out_);
            if ((out_ < 0.0) != (s.c < 0.0)) {
                atomicOr(changedSide, 1u);
            }
        }
        if (onShell(l)) {
            shellNext[slot * SHELL_VOXELS + shellIndex(l)] = out_;
        } else {
            phiPool[slot * BRICK_VOXELS + v] = out_;
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        slotState[slot] = brickState();
        if (changedSide != 0u) {
            atomicMax(ctrl.lastChange, ctrl.iteration);
            ctrl.lastChangeTime = ctrl.time;
        }
    }
}
