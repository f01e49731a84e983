// Each slot keeps the speed of its brick's voxels, barrierSpeed(dataSpeed) before the alpha
// weighting, because it only changes when the speed does (a new speed, T, eps, alpha or a
// barrier: the host then forgets every slot's, GpuBrickPool::forgetSpeed) while a brick is
// stepped hundreds of times: on llvmpipe the texture reads and the barrier loop were more than
// half of measure_speed's and update_phi's time. measure_speed fills a slot's speeds the first
// time it lists the brick; update_phi reads them in the same iteration.
// Layout (host: app/solver/gpu_brick_pool.hpp): the first `capacity` words are tags, 1 + the
// brick whose speeds the slot holds (0: none); slot s's speeds follow at capacity + s *
// BRICK_VOXELS, as float bits. A tag names the brick, not only the slot, so slots that move
// (a shrink) or change hands (retired, then allocated) never read another brick's speeds.
// Include after common/brick_pool.glsl.
layout(std430, binding = SPEED_CACHE_BINDING) buffer SpeedCache { uint speedCache[]; };

uint speedCapacity() { return uint(speedCache.length()) / (BRICK_VOXELS + 1u); }

bool speedCached(uint slot, uint brick) { return speedCache[slot] == brick + 1u; }

void markSpeedCached(uint slot, uint brick) { speedCache[slot] = brick + 1u; }

uint speedIndex(uint slot, uint v) { return speedCapacity() + slot * BRICK_VOXELS + v; }

float cachedSpeed(uint slot, uint v) { return uintBitsToFloat(speedCache[speedIndex(slot, v)]); }

float storeSpeed(uint slot, uint v, float speed) {
    speedCache[speedIndex(slot, v)] = floatBitsToUint(speed);
    return speed;
}
