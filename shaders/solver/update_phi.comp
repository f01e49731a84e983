#version 310 es
// One group per active brick: one step of phi (phi_stencil.glsl) from the brick and a one-voxel
// apron staged in shared memory; records the brick's new state and whether any voxel changed
// side (convergence), and counts the voxels that changed side with the box of those that came
// inside (the leak watch: app/solver/leak_watch.hpp), and whether the brick and its faces
// moved by more than the sleep tolerance (solver_common.glsl's QUIET_SHIFT). phi is stored once: the interior is updated in place, the shell goes to
// shellNext until commit_shells (solver/brick_shell.glsl).
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#define DATA_SPEED_INTENSITY_UNIT SOLVER_SCAN_UNIT
#define DATA_SPEED_FACTOR_UNIT SOLVER_FACTOR_UNIT
#include "speed/data_speed.glsl"
#include "solver/barrier_speed.glsl"
#include "solver/phi_stencil.glsl"
#include "solver/brick_state.glsl"
#include "solver/phi_tile.glsl"
#include "solver/brick_shell.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;
uniform float sleepTolerance; // voxels per step
// Where phi may change (LevelSetSolver::setReach): centre (voxel indices) and radius (voxels) of
// a correction's reach; radius <= 0: everywhere. Outside, the step leaves phi as it is, so the
// surface there stays what the operator accepted, whatever the speed says.
uniform vec4 reach;

bool inReach(ivec3 g) {
    vec3 q = vec3(g) - reach.xyz;
    return reach.w <= 0.0 || dot(q, q) <= reach.w * reach.w;
}

shared uint changedSide;
shared uint movedAny;
shared uint movedFaces;
shared uint gained;
shared uint lost;
shared uint gainLo[3];
shared uint gainHi[3];

// Every invocation reaches both barriers (GLSL ES 3.10): groups past the list only skip work.
void main() {
    uint n = activeListIndex();
    bool hasWork = n != NO_BRICK;
    uint slot = hasWork ? activeList[n] : 0u;
    ivec3 origin = hasWork ? brickCoord(slotBrick[slot]) * BRICK_SIZE : ivec3(0);
    if (hasWork) {
        loadTile(origin);
    }
    beginBrickState();
    if (gl_LocalInvocationIndex == 0u) {
        changedSide = 0u;
        movedAny = 0u;
        movedFaces = 0u;
        gained = 0u;
        lost = 0u;
        for (int a = 0; a < 3; ++a) {
            gainLo[a] = 0xFFFFFFFFu;
            gainHi[a] = 0u;
        }
    }
    barrier();
    float dt = ctrl.dt;
    float tolerance = sleepTolerance;
    for (uint v = gl_LocalInvocationIndex; hasWork && v < BRICK_VOXELS; v += uint(LOCAL_SIZE)) {
        ivec3 l = localVoxel(v);
        ivec3 g = origin + l;
        PhiStencil s = tileStencil(l);
        float out_ = s.c;
        if (all(lessThan(g, volumeDims))) {
            if (dt > 0.0 && inNarrowBand(s) && inReach(g)) {
                out_ = phiStep(s, barrierSpeed(g, dataSpeed(g)), alpha, dt);
            }
            noteVoxelState(l, out_);
            if (abs(out_ - s.c) > tolerance) {
                atomicOr(movedAny, 1u);
                atomicOr(movedFaces, facesOf(l));
            }
            if ((out_ < 0.0) != (s.c < 0.0)) {
                atomicOr(changedSide, 1u);
                if (out_ < 0.0) {
                    atomicAdd(gained, 1u);
                    for (int a = 0; a < 3; ++a) {
                        atomicMin(gainLo[a], uint(g[a]));
                        atomicMax(gainHi[a], uint(g[a]));
                    }
                } else {
                    atomicAdd(lost, 1u);
                }
            }
        }
        if (onShell(l)) {
            shellNext[slot * SHELL_VOXELS + shellIndex(l)] = out_;
        } else {
            phiPool[slot * BRICK_VOXELS + v] = out_;
        }
    }
    barrier();
    if (hasWork && gl_LocalInvocationIndex == 0u) {
        // No step (a stall, the time limit) says nothing about motion: the count stays.
        uint quiet = quietOf(slotState[slot]);
        if (dt > 0.0) {
            quiet = movedAny != 0u ? 0u : min(quiet + 1u, 255u);
        }
        slotState[slot] = brickState() | (quiet << QUIET_SHIFT) | (movedFaces << MOVED_SHIFT);
        if (changedSide != 0u) {
            atomicMax(ctrl.lastChange, ctrl.iteration);
            ctrl.lastChangeTime = ctrl.time;
            atomicAdd(ctrl.gained, gained);
            atomicAdd(ctrl.lost, lost);
            for (int a = 0; a < 3; ++a) {
                atomicMin(ctrl.gainLo[a], gainLo[a]);
                atomicMax(ctrl.gainHi[a], gainHi[a]);
            }
        }
    }
}
