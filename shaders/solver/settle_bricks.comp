#version 310 es
// After a step or an edit, one dispatch (it was three: commit_shells, retire_bricks,
// mark_wanted_bricks, each behind a memory barrier; issue 50). Its first activeCount groups
// commit the shells update_phi set aside into the pool, completing the in-place step
// (solver/brick_shell.glsl), with commitShells only: an edit leaves no shell aside. The rest run
// one thread per used slot (bandList, asleep or awake) that
// - retires a brick that became uniform (all -PHI_FAR or all +PHI_FAR) and that no face
//   neighbour's band reaches: it gives its slot back and becomes BRICK_INSIDE / BRICK_OUTSIDE
//   (not in dense mode, whose every brick keeps its slot);
// - wakes the neighbours whose stencils read a face its step moved by more than the sleep
//   tolerance (across the face, and across an edge of two moved faces: the stencil has face and
//   edge neighbours, no corners);
// - asks, for a live brick, for storage for a constant face neighbour when the band reaches the
//   face they share (a voxel on it has |phi| < PHI_FAR, so the voxels across it step next
//   iteration; solver_common.glsl's FACE_REACH_SHIFT). wantEpoch keeps each brick to one
//   request per pass.
// The three were separate passes only by history: nothing one writes is read by another here.
// Commits write phi, which neither other part reads. A brick retires under the same rule as the
// one by which its neighbours request storage (a neighbour reaches its face), so a brick that
// retires is never one a live neighbour requests, whether that neighbour's thread reads the page
// table before or after the retirement; a wake that reaches a slot retiring at the same time
// clears the quiet count of a free slot, which its next allocation overwrites. Retirement does
// not change any slot's state word, which the other threads read.
// The last group to finish prepares the next iteration (solver_common.glsl's beginIteration; it
// was begin_iteration's one thread), keeping this one's counts for the host first.
#define PAGE_TABLE_ACCESS
#define PHI_POOL_ACCESS
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
#include "solver/brick_shell.glsl"
layout(local_size_x = 64) in;

layout(std430, binding = FREE_LIST_BINDING) buffer FreeList { uint freeList[]; };
layout(std430, binding = REQUESTS_BINDING) writeonly buffer Requests { uint requests[]; };
layout(std430, binding = WANT_EPOCH_BINDING) buffer WantEpoch { uint wantEpoch[]; };

uniform uint epoch;
uniform bool commitShells;
uniform bool retire;

void commitShell(uint slot) {
    for (uint i = gl_LocalInvocationIndex; i < SHELL_VOXELS; i += 64u) {
        ivec3 l = shellVoxel(i);
        uint v = uint(l.x + BRICK_SIZE * (l.y + BRICK_SIZE * l.z));
        phiPool[slot * BRICK_VOXELS + v] = shellNext[slot * SHELL_VOXELS + i];
    }
}

// Whether the slot (holding brick b, state word `word`) gave its slot back.
bool retireSlot(uint slot, uint word, ivec3 b) {
    uint state = stateOf(word);
    if (state == STATE_LIVE || state == STATE_MIXED) {
        return false;
    }
    for (int f = 0; f < 6; ++f) {
        ivec3 nb = b + FACE_NEIGHBOURS[f];
        if (brickInGrid(nb)) {
            uint s = pageTable[brickIndex(nb)];
            // FACE_NEIGHBOURS pairs opposite faces: f ^ 1 is the neighbour's face towards us.
            if (s < BRICK_INSIDE && reachesFace(slotState[s], f ^ 1)) {
                return false;
            }
        }
    }
    pageTable[brickIndex(b)] = state == STATE_INSIDE ? BRICK_INSIDE : BRICK_OUTSIDE;
    slotBrick[slot] = NO_BRICK;
    freeList[atomicAdd(ctrl.freeCount, 1u)] = slot;
    return true;
}

void wakeReaders(uint word, ivec3 b) {
    uint moved = word >> MOVED_SHIFT;
    for (int d = 0; moved != 0u && d < 27; ++d) {
        ivec3 o = ivec3(d % 3, (d / 3) % 3, d / 9) - 1;
        int axes = abs(o.x) + abs(o.y) + abs(o.z);
        uvec3 faceBit = uvec3(1u, 4u, 16u) << uvec3(greaterThan(o, ivec3(0)));
        uvec3 need = uvec3(notEqual(o, ivec3(0))) * faceBit;
        uint needed = need.x | need.y | need.z;
        ivec3 nb = b + o;
        if (axes == 0 || axes == 3 || (moved & needed) != needed || !brickInGrid(nb)) {
            continue;
        }
        uint s = pageTable[brickIndex(nb)];
        if (s < BRICK_INSIDE) {
            atomicAnd(slotState[s], ~QUIET_MASK);
        }
    }
}

void requestNeighbours(uint word, ivec3 b) {
    if (stateOf(word) != STATE_LIVE) {
        return;
    }
    for (int f = 0; f < 6; ++f) {
        ivec3 nb = b + FACE_NEIGHBOURS[f];
        if (!reachesFace(word, f) || !brickInGrid(nb)) {
            continue;
        }
        uint brick = brickIndex(nb);
        if (pageTable[brick] >= BRICK_INSIDE && atomicExchange(wantEpoch[brick], epoch) != epoch) {
            requests[atomicAdd(ctrl.requestCount, 1u)] = brick;
        }
    }
}

// Every invocation reaches the barrier (GLSL ES 3.10): groups and threads past the lists only
// skip work.
void main() {
    uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * GROUPS_PER_ROW;
    uint shellGroups = ctrl.activeCount;
    if (group < shellGroups) {
        if (commitShells) {
            commitShell(activeList[group]);
        }
    } else {
        uint n = (group - shellGroups) * 64u + gl_LocalInvocationIndex;
        if (n < ctrl.bandCount) {
            uint slot = bandList[n];
            uint word = slotState[slot];
            ivec3 b = brickCoord(slotBrick[slot]);
            if (retire) {
                retireSlot(slot, word, b);
            }
            wakeReaders(word, b);
            requestNeighbours(word, b);
        }
    }
    memoryBarrierBuffer(); // this invocation's counts, before its group counts itself done
    barrier();
    if (gl_LocalInvocationIndex == 0u && lastGroupDone()) {
        ctrl.shownActive = ctrl.activeCount;
        ctrl.shownBand = ctrl.bandCount;
        ctrl.shownFront = ctrl.frontVoxels;
        beginIteration();
    }
}
