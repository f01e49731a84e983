#version 310 es
// The classifier speed at every voxel (speed/classifier_forest.glsl). One invocation per voxel,
// 4x4x4 voxels per group, so a scan of up to 262140 voxels a side stays within the 65535 groups a
// dimension allows; the host dispatches slabs of slices from zOffset, so no single dispatch runs
// long enough on a large scan to trip a GPU watchdog.
precision highp float;
precision highp int;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"
#include "speed/classifier_forest.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(r32f, binding = SPEED_OUT_IMAGE_UNIT) uniform writeonly image3D speedOut;
uniform int zOffset;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, zOffset);
    if (any(greaterThanEqual(v, classifierDims))) {
        return;
    }
    imageStore(speedOut, v, vec4(classifierSpeedAt(v), 0.0, 0.0, 0.0));
}
