// Bookkeeping buffers of the sparse solver (host mirror: app/solver/gpu_brick_pool.hpp).
// Include after common/brick_pool.glsl (which brings the binding points, common/bindings.h).
// Slots are pool slots; "brick" is a brick's linear index.
#ifndef LOCAL_SIZE
#define LOCAL_SIZE 512
#endif

const uint NO_BRICK = 0xFFFFFFFFu;
// Per-slot state after the last update: does the brick hold the surface's narrow band?
const uint STATE_LIVE = 0u;    // some voxel has |phi| < PHI_FAR
const uint STATE_INSIDE = 1u;  // every voxel at -PHI_FAR: may retire to BRICK_INSIDE
const uint STATE_OUTSIDE = 2u; // every voxel at +PHI_FAR: may retire to BRICK_OUTSIDE
const uint STATE_MIXED = 3u;   // clamped values of both signs: kept
const uint STATE_MASK = 0xFFu;
// Above the state, bit FACE_REACH_SHIFT + f: a voxel on the brick's face f (FACE_NEIGHBOURS
// order) has |phi| < PHI_FAR, so the voxels across that face are in the narrow band (they have
// an unclamped face neighbour) and the brick there needs storage. Only such a face lets the band
// into a constant neighbour: its other voxels' face neighbours are all clamped.
const uint FACE_REACH_SHIFT = 8u;
// Sleeping (docs/solver.md, "Sleeping bricks"): bits QUIET_SHIFT.. count the iterations in a row
// in which no voxel of the brick moved by more than the tolerance (saturating at 255); a brick
// whose count reached sleepAfter is left out of the active list. Bits MOVED_SHIFT + f: in the
// last step a voxel on face f moved by more than the tolerance, so the bricks whose stencils
// read that face must be awake (settle_bricks clears their count).
const uint QUIET_SHIFT = 16u;
const uint QUIET_MASK = 0xFFu << QUIET_SHIFT;
const uint MOVED_SHIFT = 24u;

uint quietOf(uint slotWord) { return (slotWord & QUIET_MASK) >> QUIET_SHIFT; }

uint stateOf(uint slotWord) { return slotWord & STATE_MASK; }

bool reachesFace(uint slotWord, int face) {
    return (slotWord & (1u << (FACE_REACH_SHIFT + uint(face)))) != 0u;
}

// Groups over the active list are laid out 2D (x < 1024) to stay under the 65535 group limit.
const uint GROUPS_PER_ROW = 1024u;

layout(std430, binding = CONTROL_BINDING) coherent buffer Control {
    uint allocArgs[3]; // indirect dispatch: one group per requested brick
    uint brickArgs[3]; // indirect dispatch: one group per active brick
    uint settleArgs[3]; // indirect dispatch: settle_bricks (activeCount groups, 64 slots a group)
    uint requestCount; // bricks asking for a slot (neighbours of the band, sphere edits)
    uint activeCount;  // entries of activeList
    uint freeCount;    // entries of freeList
    uint popped;       // slots taken from freeList by the current allocation pass
    uint stalled;      // non-zero: a request found no free slot; iterations pause until the host grows the pool
    uint maxRateBits;  // max |alpha * D| over the narrow band, as float bits (non-negative)
    float dt;          // this iteration's time step (0: no step)
    float time;        // evolved time
    uint iteration;    // iterations performed
    uint lastChange;   // iteration in which a voxel last changed side
    float lastChangeTime;
    uint peakActive;
    // The leak watch's counters since the host last cleared them (every check): voxels that
    // came inside and went outside, and the box of those that came inside (min > max: none).
    uint gained;
    uint lost;
    uint gainLo[3];
    uint gainHi[3];
    // Sleeping: every used slot (bandList, for the passes that keep the band's bookkeeping),
    // the active bricks summed over the iterations performed since the host last cleared it
    // (voxels visited), and the front's voxels in this iteration (asleep: as last measured).
    uint bandCount;
    uint visitedBricks;
    uint frontVoxels;
    // Work groups of the current pass that have finished (lastGroupDone).
    uint groupsDone;
    // The last iteration's activeCount, bandCount and frontVoxels, for the host: settle_bricks
    // clears the working counters for the next iteration before the host reads them.
    uint shownActive;
    uint shownBand;
    uint shownFront;
    // Active bricks whose front measure_speed measures (measureListBase), and its dispatch.
    uint measureCount;
    uint measureArgs[3];
} ctrl;

layout(std430, binding = SLOT_BRICK_BINDING) buffer SlotBrick { uint slotBrick[]; };
// Two lists of up to a slot each: the active bricks from 0, and from measureListBase() those of
// them measure_speed measures (the rest keep their last measure: build_active_list).
layout(std430, binding = ACTIVE_LIST_BINDING) buffer ActiveList { uint activeList[]; };

uint measureListBase() { return uint(activeList.length()) / 2u; }
layout(std430, binding = SLOT_STATE_BINDING) buffer SlotState { uint slotState[]; }; // state | reach
layout(std430, binding = BAND_LIST_BINDING) buffer BandList { uint bandList[]; };
// Per slot, as measure_speed last saw it: [2 s] max |alpha D| on its front (float bits),
// [2 s + 1] its front's voxels; a sleeping brick contributes them unchanged.
layout(std430, binding = SLOT_FRONT_BINDING) buffer SlotFront { uint slotFront[]; };

ivec3 brickCoord(uint brick) {
    int b = int(brick);
    return ivec3(b % brickGrid.x, (b / brickGrid.x) % brickGrid.y, b / (brickGrid.x * brickGrid.y));
}

bool brickInGrid(ivec3 b) { return all(greaterThanEqual(b, ivec3(0))) && all(lessThan(b, brickGrid)); }

ivec3 localVoxel(uint n) {
    int i = int(n);
    return ivec3(i % BRICK_SIZE, (i / BRICK_SIZE) % BRICK_SIZE, i / (BRICK_SIZE * BRICK_SIZE));
}

// Index into the active list of this work group (one group per active brick), or NO_BRICK.
uint activeListIndex() {
    uint n = gl_WorkGroupID.x + gl_WorkGroupID.y * GROUPS_PER_ROW;
    return n < ctrl.activeCount ? n : NO_BRICK;
}

// One pass's bookkeeping done by the group that finishes last, instead of a one-thread dispatch
// of its own behind one more memory barrier (issue 50). Each group counts itself into
// ctrl.groupsDone once its work is written; the group whose count completes the pass then sees
// every other group's results. Why that holds on any GPU, not only on one that runs groups in
// order: Control is `coherent` (no read is served from a core's stale cache), every counter the
// bookkeeping reads is updated with atomics in the pass and read back with atomics by the last
// group (performed at the device's point of coherence), every invocation that updates one calls
// memoryBarrierBuffer() before its group's barrier() and the counting invocation calls it again
// before its count (release: the group's updates are complete before it counts), and the last
// group calls it after its count, before its reads (acquire). Call from one invocation of each
// group, after `memoryBarrierBuffer(); barrier();` at main()'s top level where other invocations
// update counters; every group of the dispatch must call it. It resets the count for the next
// pass (the host's glMemoryBarrier between dispatches orders the reset before that pass).
bool lastGroupDone() {
    uint groups = gl_NumWorkGroups.x * gl_NumWorkGroups.y * gl_NumWorkGroups.z;
    memoryBarrierBuffer();
    bool last = atomicAdd(ctrl.groupsDone, 1u) == groups - 1u;
    if (last) {
        memoryBarrierBuffer();
        ctrl.groupsDone = 0u;
    }
    return last;
}

// Indirect dispatch arguments for n groups, GROUPS_PER_ROW to a row.
uvec3 groupsFor(uint n) {
    return uvec3(min(n, GROUPS_PER_ROW), (n + GROUPS_PER_ROW - 1u) / GROUPS_PER_ROW, 1u);
}

// Before an iteration: the allocation's dispatch size from the requests the band asked for
// (mark in settle_bricks, or an edit's request_edit_bricks), and the counters of the passes
// over the lists cleared. Run by begin_iteration (after an edit) and settle_bricks's last group.
void beginIteration() {
    uvec3 alloc = groupsFor(atomicAdd(ctrl.requestCount, 0u));
    ctrl.allocArgs[0] = alloc.x;
    ctrl.allocArgs[1] = alloc.y;
    ctrl.allocArgs[2] = alloc.z;
    ctrl.popped = 0u;
    ctrl.activeCount = 0u;
    ctrl.maxRateBits = 0u;
    ctrl.bandCount = 0u;
    ctrl.frontVoxels = 0u;
    ctrl.measureCount = 0u;
}

const ivec3 FACE_NEIGHBOURS[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0),
                                          ivec3(0, 1, 0), ivec3(0, 0, -1), ivec3(0, 0, 1));
