#version 310 es
// One thread: dt = courant / (max |alpha * D| + fixedRate) (TimeStepRule in
// app/solver/level_set_params.hpp), cut to reach timeLimit exactly; no step while stalled.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 1) in;

uniform float courant;
uniform float fixedRate;
uniform float timeLimit;

void main() {
    float dt = courant / (uintBitsToFloat(ctrl.maxRateBits) + fixedRate);
    dt = min(dt, timeLimit - ctrl.time);
    if (ctrl.stalled != 0u || !(dt > 0.0)) {
        dt = 0.0;
    }
    ctrl.dt = dt;
    if (dt > 0.0) {
        ctrl.time += dt;
        ctrl.iteration += 1u;
    }
}
