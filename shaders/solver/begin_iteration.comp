#version 310 es
// One thread, after an edit's request_edit_bricks or an upload: the allocation's dispatch size
// and cleared counters (solver_common.glsl's beginIteration). Within a run of iterations
// settle_bricks's last group does the same, so an iteration has no dispatch for it.
#include "common/brick_pool.glsl"
#include "solver/solver_common.glsl"
layout(local_size_x = 1) in;

void main() {
    beginIteration();
}
