#version 310 es
// The classifier speed at every voxel: the features, then the mean over the forest's trees of
// the leaf's P(inside) - P(outside). One invocation per voxel, 4x4x4 voxels per group, so a
// scan of up to 262140 voxels a side stays within the 65535 groups a dimension allows; the host
// dispatches slabs of slices from zOffset, so no single dispatch runs long enough on a large
// scan to trip a GPU watchdog.
precision highp float;
precision highp int;
precision highp sampler3D;
precision highp image3D;

#include "common/bindings.h"
#include "speed/classifier_features.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

// A split sends f[feature] < threshold to `left`, the rest to left + 1; a leaf (feature < 0)
// holds its value. The same layout as speed::ForestNode.
struct ForestNode {
    int feature;
    float threshold;
    int left;
    float value;
};
layout(std430, binding = CLASSIFIER_NODES_BINDING) readonly buffer Nodes {
    ForestNode nodes[];
};
layout(std430, binding = CLASSIFIER_ROOTS_BINDING) readonly buffer Roots {
    int roots[];
};
layout(r32f, binding = SPEED_OUT_IMAGE_UNIT) uniform writeonly image3D speedOut;
uniform int treeCount;
uniform int maxDepth; // bounds each walk, whatever the buffer holds
uniform int zOffset;

void main() {
    ivec3 v = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, zOffset);
    if (any(greaterThanEqual(v, classifierDims))) {
        return;
    }
    float f[CLASSIFIER_FEATURE_COUNT];
    classifierFeatures(v, f);
    float sum = 0.0;
    for (int t = 0; t < treeCount; ++t) {
        ForestNode node = nodes[roots[t]];
        for (int depth = 0; depth < maxDepth && node.feature >= 0; ++depth) {
            node = nodes[node.left + (f[node.feature] < node.threshold ? 0 : 1)];
        }
        sum += node.value;
    }
    imageStore(speedOut, v, vec4(sum / float(treeCount), 0.0, 0.0, 0.0));
}
