#version 310 es
// The forest's walk over given feature rows (speed/classifier_forest.glsl's classifierLook): the
// CPU twin's features in, the looks out, with no vote of the marks. The numerics check compares
// them with the CPU forest's beside the evaluation, which computes its features itself, so that
// a GPU that gets the walk wrong and one that gets the features wrong tell apart.
precision highp float;
precision highp int;
precision highp sampler3D;

#include "common/bindings.h"
#include "speed/classifier_forest.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = CLASSIFIER_FEATURES_BINDING) readonly buffer Rows {
    float rowFeatures[];
};
layout(std430, binding = CLASSIFIER_SAMPLES_BINDING) writeonly buffer Looks {
    float looks[];
};
uniform int rowCount;

void main() {
    int r = int(gl_GlobalInvocationID.x);
    if (r >= rowCount) {
        return;
    }
    int b = r * CLASSIFIER_FEATURE_COUNT;
    ClassifierFeatureVector f;
    f.lo = vec4(rowFeatures[b], rowFeatures[b + 1], rowFeatures[b + 2], rowFeatures[b + 3]);
    f.hi = vec4(rowFeatures[b + 4], rowFeatures[b + 5], rowFeatures[b + 6], rowFeatures[b + 7]);
    looks[r] = classifierLook(f);
}
