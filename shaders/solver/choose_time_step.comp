#version 310 es
// One thread: dt = 1 / (max |alpha * D| / courant + fixedRate), fixedRate = the rescaling
// term's speed / courant + the curvature term's diffusion rate (the bound it obeys: TimeStepRule
// in app/solver/level_set_params.hpp), cut to reach timeLimit exactly; no step while stalled.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 1) in;

uniform float courant;
uniform float fixedRate;
uniform float timeLimit;

void main() {
    float dt = 1.0 / (uintBitsToFloat(ctrl.maxRateBits) / courant + fixedRate);
    dt = min(dt, timeLimit - ctrl.time);
    if (ctrl.stalled != 0u || !(dt > 0.0)) {
        dt = 0.0;
    }
    ctrl.dt = dt;
    if (dt > 0.0) {
        ctrl.time += dt;
        ctrl.iteration += 1u;
        ctrl.visitedBricks += ctrl.activeCount;
    }
}
