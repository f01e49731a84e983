#version 310 es
// The data term at every voxel (speed/data_speed.glsl, the definition the solver steps with),
// into an R32F texture, for the numerics check to hold against its CPU twin (solver's
// phi_stencil.hpp dataSpeed) on the GPU the appliance runs on.
precision highp float;
precision highp int;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"
#define DATA_SPEED_INTENSITY_UNIT SOLVER_SCAN_UNIT
#define DATA_SPEED_FACTOR_UNIT SOLVER_FACTOR_UNIT
#include "speed/data_speed.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(r32f, binding = SPEED_OUT_IMAGE_UNIT) uniform writeonly image3D speedOut;
uniform ivec3 volumeDims;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, volumeDims))) {
        return;
    }
    imageStore(speedOut, v, vec4(dataSpeed(v), 0.0, 0.0, 0.0));
}
