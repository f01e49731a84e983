#version 310 es
// One group per active brick: one step of phi (phi_stencil.glsl) from the brick and a one-voxel
// apron staged in shared memory, at the speeds measure_speed kept for it (speed_cache.glsl);
// records the brick's new state and whether any voxel changed side (convergence), and counts
// the voxels that changed side with the box of those that came inside (the leak watch:
// app/solver/leak_watch.hpp), and whether the brick and its faces moved by more than the sleep
// tolerance (solver_common.glsl's QUIET_SHIFT), and which voxels are inside (the sign rows
// measure_speed finds the next front from: speed_cache.glsl). phi is stored once: the interior
// is updated in place, the shell goes to shellNext until settle_bricks commits it
// (solver/brick_shell.glsl).
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/phi_stencil.glsl"
#include "solver/brick_state.glsl"
#include "solver/phi_tile.glsl"
#include "solver/brick_shell.glsl"
#include "solver/speed_cache.glsl"
#include "solver/sphere_metric.glsl"
layout(local_size_x = LOCAL_SIZE) in;

uniform float alpha;
uniform float sleepTolerance; // voxels per step
// Where phi may change (LevelSetSolver::setReach): centre (voxel indices) and radius (voxels) of
// a correction's reach; radius <= 0: everywhere. Outside, the step leaves phi as it is, so the
// surface there stays what the operator accepted, whatever the speed says; with recedeOutside
// phi there may only rise: the surface withdraws from what the speed refuses, and advances
// nowhere (an erase's run that grew too far, model::Reach).
uniform vec4 reach;
uniform bool recedeOutside;

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
        loadTile(origin, slot);
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
    // This invocation's voxels, added to the group's once after the loop (see brick_state.glsl).
    uint state = 0u;
    bool movedMine = false;
    uint movedFacesMine = 0u;
    uint gainedMine = 0u;
    uint lostMine = 0u;
    uvec3 gainLoMine = uvec3(0xFFFFFFFFu);
    uvec3 gainHiMine = uvec3(0u);
    // An invocation steps rows of voxels along x, keeping the x - 1, x, x + 1 values of the row
    // and of the four rows beside it (y -+ 1, z -+ 1) as it goes: 5 tile reads a voxel for its
    // faces and x edges instead of 19 (and 4 more for the yz edges where it steps), the same
    // stencil to the bit. llvmpipe gathers each shared-memory read lane by lane.
    const int ROWS = BRICK_SIZE * BRICK_SIZE;
    for (int row = int(gl_LocalInvocationIndex); hasWork && row < ROWS; row += LOCAL_SIZE) {
        int y = row % BRICK_SIZE;
        int z = row / BRICK_SIZE;
        float c0 = tileAt(ivec3(-1, y, z));
        float c1 = tileAt(ivec3(0, y, z));
        float ym0 = tileAt(ivec3(-1, y - 1, z));
        float ym1 = tileAt(ivec3(0, y - 1, z));
        float yp0 = tileAt(ivec3(-1, y + 1, z));
        float yp1 = tileAt(ivec3(0, y + 1, z));
        float zm0 = tileAt(ivec3(-1, y, z - 1));
        float zm1 = tileAt(ivec3(0, y, z - 1));
        float zp0 = tileAt(ivec3(-1, y, z + 1));
        float zp1 = tileAt(ivec3(0, y, z + 1));
        uint signs = 0u;
        for (int x = 0; x < BRICK_SIZE; ++x) {
            float c2 = tileAt(ivec3(x + 1, y, z));
            float ym2 = tileAt(ivec3(x + 1, y - 1, z));
            float yp2 = tileAt(ivec3(x + 1, y + 1, z));
            float zm2 = tileAt(ivec3(x + 1, y, z - 1));
            float zp2 = tileAt(ivec3(x + 1, y, z + 1));
            ivec3 l = ivec3(x, y, z);
            uint v = uint(x + BRICK_SIZE * row);
            ivec3 g = origin + l;
            // tileFaces(l): the centre and its faces, edges left at 0.
            PhiStencil s = PhiStencil(c1, c0, c2, ym1, yp1, zm1, zp1, 0.0, 0.0, 0.0, 0.0, 0.0,
                                      0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
            float out_ = s.c;
            if (all(lessThan(g, volumeDims))) {
                bool within = inReach(vec3(g), reach);
                if (dt > 0.0 && inNarrowBand(s) && (within || recedeOutside)) {
                    // The 12 edge neighbours, only where a step reads them.
                    s.xpyp = yp2;
                    s.xpym = ym2;
                    s.xmyp = yp0;
                    s.xmym = ym0;
                    s.xpzp = zp2;
                    s.xpzm = zm2;
                    s.xmzp = zp0;
                    s.xmzm = zm0;
                    s.ypzp = tileAt(l + ivec3(0, 1, 1));
                    s.ypzm = tileAt(l + ivec3(0, 1, -1));
                    s.ymzp = tileAt(l + ivec3(0, -1, 1));
                    s.ymzm = tileAt(l + ivec3(0, -1, -1));
                    // At the speed measure_speed kept.
                    float next = phiStep(s, cachedSpeed(slot, v), alpha, dt);
                    out_ = within ? next : max(next, s.c);
                }
                state |= voxelState(l, out_);
                if (abs(out_ - s.c) > tolerance) {
                    movedMine = true;
                    movedFacesMine |= facesOf(l);
                }
                if ((out_ < 0.0) != (s.c < 0.0)) {
                    if (out_ < 0.0) {
                        ++gainedMine;
                        gainLoMine = min(gainLoMine, uvec3(g));
                        gainHiMine = max(gainHiMine, uvec3(g));
                    } else {
                        ++lostMine;
                    }
                }
            }
            signs |= uint(out_ < 0.0) << uint(x);
            if (onShell(l)) {
                shellNext[slot * SHELL_VOXELS + shellIndex(l)] = out_;
            } else {
                phiPool[slot * BRICK_VOXELS + v] = out_;
            }
            c0 = c1;
            c1 = c2;
            ym0 = ym1;
            ym1 = ym2;
            yp0 = yp1;
            yp1 = yp2;
            zm0 = zm1;
            zm1 = zm2;
            zp0 = zp1;
            zp1 = zp2;
        }
        storeSignRow(slot, uint(row), signs);
    }
    noteBrickState(state);
    if (movedMine) {
        atomicOr(movedAny, 1u);
        atomicOr(movedFaces, movedFacesMine);
    }
    if (gainedMine + lostMine > 0u) {
        atomicOr(changedSide, 1u);
        atomicAdd(gained, gainedMine);
        atomicAdd(lost, lostMine);
    }
    if (gainedMine > 0u) {
        for (int a = 0; a < 3; ++a) {
            atomicMin(gainLo[a], gainLoMine[a]);
            atomicMax(gainHi[a], gainHiMine[a]);
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
        noteSignsKept(slot, true);
        if (changedSide != 0u) {
            noteSideChanged(slot, ctrl.iteration); // measure_speed measures it and its neighbours
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
