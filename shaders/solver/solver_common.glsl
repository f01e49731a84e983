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
// read that face must be awake (mark_wanted_bricks clears their count).
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
    uint listArgs[3];  // indirect dispatch: one thread per used slot (bandList), 64 per group
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
} ctrl;

layout(std430, binding = SLOT_BRICK_BINDING) buffer SlotBrick { uint slotBrick[]; };
layout(std430, binding = ACTIVE_LIST_BINDING) buffer ActiveList { uint activeList[]; };
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

const ivec3 FACE_NEIGHBOURS[6] = ivec3[6](ivec3(-1, 0, 0), ivec3(1, 0, 0), ivec3(0, -1, 0),
                                          ivec3(0, 1, 0), ivec3(0, 0, -1), ivec3(0, 0, 1));
