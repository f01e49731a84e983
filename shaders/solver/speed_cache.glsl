// What measure_speed keeps per slot between steps, beside its outputs in slotFront.
// - The speeds of the brick's voxels, barrierSpeed(dataSpeed) before the alpha weighting: they
//   only change when the speed does (a new speed, T, eps, alpha or a barrier: the host then
//   forgets every slot's, GpuBrickPool::forgetSpeed) while a brick is stepped hundreds of times,
//   and on llvmpipe the texture reads and the barrier loop were a large part of measure_speed's
//   and update_phi's time. measure_speed fills a slot's the first time it lists the brick;
//   update_phi reads them in the same iteration.
// - When its front last changed: the front's maximum and voxel count depend only on the speeds
//   and on which side of the surface the brick's voxels and its face neighbours' lie, and in a
//   step only about one active brick in ten has a voxel change side. measure_speed measures a
//   brick again only when it or a face neighbour did since it last measured it (or its speeds
//   were forgotten); otherwise it adds the slot's last measure, as build_active_list does for a
//   sleeping brick.
// - Which of its voxels are inside (phi < 0), a row of bits a row of voxels: the front is where a
//   voxel's bit differs from a face neighbour's, so measure_speed finds it from these words and
//   its neighbours' instead of loading the brick's phi and its apron (on llvmpipe that load was
//   most of the pass). update_phi writes them with the values it stores, allocate_bricks a new
//   slot's constant ones; they stand until the host changes the level set outside a step.
// Layout (host: app/solver/gpu_brick_pool_speed.cpp), C = the slots: [0, C) tags, 1 + the brick
// whose speeds the slot holds (0: none); [C, 2C) the step count after which a voxel last changed
// side in the slot (update_phi); [2C, 3C) 1 + the step count at which measure_speed last
// measured it (0: never); [3C, 4C) non-zero while the slot's sign rows hold its phi's signs (the
// host clears these two runs when the level set changes outside a step, and allocate_bricks when
// a slot changes hands); then slot s's speeds at 4C + s * BRICK_VOXELS, as float bits; then its
// sign rows at 4C + C * BRICK_VOXELS + s * SIGN_ROWS, row y + BRICK_SIZE * z holding bit x for
// voxel (x, y, z). A tag names the brick, not only the slot, so slots that move (a shrink) or
// change hands (retired, then allocated) never read another brick's speeds.
// Include after common/brick_pool.glsl.
layout(std430, binding = SPEED_CACHE_BINDING) buffer SpeedCache { uint speedCache[]; };

// The header's runs (one word a slot each) in order, as the host names them.
const uint SIDE_CHANGE_RUN = 1u;
const uint MEASURE_RUN = 2u;
const uint SIGNS_RUN = 3u;
const uint HEADER_RUNS = 4u;
const uint SIGN_ROWS = uint(BRICK_SIZE * BRICK_SIZE);
const uint ROW_BITS = (1u << uint(BRICK_SIZE)) - 1u; // a row of voxels all inside

uint speedCapacity() {
    return uint(speedCache.length()) / (BRICK_VOXELS + HEADER_RUNS + SIGN_ROWS);
}

// Slot `slot`'s word in header run `run`.
uint headerIndex(uint run, uint slot) { return run * speedCapacity() + slot; }

bool speedCached(uint slot, uint brick) { return speedCache[slot] == brick + 1u; }

void markSpeedCached(uint slot, uint brick) { speedCache[slot] = brick + 1u; }

uint speedIndex(uint slot, uint v) {
    return HEADER_RUNS * speedCapacity() + slot * BRICK_VOXELS + v;
}

float cachedSpeed(uint slot, uint v) { return uintBitsToFloat(speedCache[speedIndex(slot, v)]); }

float storeSpeed(uint slot, uint v, float speed) {
    speedCache[speedIndex(slot, v)] = floatBitsToUint(speed);
    return speed;
}

// After a step `steps` (the count once it is done) changed a voxel of the slot's side.
void noteSideChanged(uint slot, uint steps) {
    speedCache[headerIndex(SIDE_CHANGE_RUN, slot)] = steps;
}

uint sideChangedAt(uint slot) { return speedCache[headerIndex(SIDE_CHANGE_RUN, slot)]; }

// measure_speed measured the slot after `steps` steps.
void noteMeasured(uint slot, uint steps) {
    speedCache[headerIndex(MEASURE_RUN, slot)] = steps + 1u;
}

void forgetMeasured(uint slot) { speedCache[headerIndex(MEASURE_RUN, slot)] = 0u; }

// The slot's front may differ from its last measure: never measured, or a voxel of it or of a
// face neighbour with a slot changed side since. A neighbour without one holds a constant, which
// changes only through a slot of its own.
bool frontMayHaveChanged(uint slot, ivec3 brick) {
    uint measured = speedCache[headerIndex(MEASURE_RUN, slot)];
    if (measured == 0u || sideChangedAt(slot) >= measured) {
        return true;
    }
    for (int f = 0; f < 6; ++f) {
        ivec3 b = brick + FACE_NEIGHBOURS[f];
        if (!brickInGrid(b)) {
            continue;
        }
        uint s = pageTable[brickIndex(b)];
        if (s != BRICK_INSIDE && s != BRICK_OUTSIDE && sideChangedAt(s) >= measured) {
            return true;
        }
    }
    return false;
}

uint signRowIndex(uint slot, uint row) {
    return (HEADER_RUNS + BRICK_VOXELS) * speedCapacity() + slot * SIGN_ROWS + row;
}
// Row `row` of the slot: bit x set where voxel x of the row is inside.
uint signRow(uint slot, uint row) { return speedCache[signRowIndex(slot, row)]; }
void storeSignRow(uint slot, uint row, uint bits) { speedCache[signRowIndex(slot, row)] = bits; }
bool signsKept(uint slot) { return speedCache[headerIndex(SIGNS_RUN, slot)] != 0u; }
void noteSignsKept(uint slot, bool kept) {
    speedCache[headerIndex(SIGNS_RUN, slot)] = kept ? 1u : 0u;
}
