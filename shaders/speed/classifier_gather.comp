#version 310 es
// The training samples' features: a list of voxel coordinates in, one feature vector per
// sample out, read back once for the forest's training on the CPU.
precision highp float;
precision highp int;
precision highp sampler3D;

#include "common/bindings.h"
#include "speed/classifier_features.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = CLASSIFIER_SAMPLES_BINDING) readonly buffer Samples {
    ivec4 sampleVoxels[];
};
layout(std430, binding = CLASSIFIER_FEATURES_BINDING) writeonly buffer Features {
    float sampleFeatures[];
};
uniform int sampleCount;

void main() {
    int s = int(gl_GlobalInvocationID.x);
    if (s >= sampleCount) {
        return;
    }
    // Each feature through the accessor the forest's walk uses (speed/classifier_forest.glsl).
    ClassifierFeatureVector f = classifierFeatures(sampleVoxels[s].xyz);
    for (int n = 0; n < CLASSIFIER_FEATURE_COUNT; ++n) {
        sampleFeatures[s * CLASSIFIER_FEATURE_COUNT + n] = classifierFeature(f, n);
    }
}
