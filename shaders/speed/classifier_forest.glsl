// The classifier speed at one voxel: its features (speed/classifier_features.glsl), then the mean
// over the forest's trees of the leaf's P(inside) - P(outside), `look`; where look is unsure,
// the operator's marks near the voxel decide (speed/place_vote: +1 at an inside mark, -1 at an
// outside one, 0 beyond their reach): look + (1 - |look|) place. Appearance cannot tell a
// tumour from the tissue of its leak, but an erase in the leak and a seed in the tumour tell
// where each lies; far from every mark, look decides alone. One code for the evaluation over
// the whole scan (speed/classifier_evaluate.comp) and for the solver's evaluation of the bricks
// the front reaches (solver/evaluate_speed.comp), so both give the same number at a voxel.
#include "speed/classifier_features.glsl"

// A split sends f[feature] < threshold to `left`, the rest to left + 1; a leaf (feature < 0)
// holds its value. speed::ForestNode's 16 bytes, read as four words (feature, threshold's bits,
// left, value's bits), by index. On NVIDIA's driver 580 (H200, bench/classifier_walk_probe) a
// walk that copied the node as a struct and assigned the next node over it in the loop took
// the first step right and every later one wrong, whatever held the features; reading the
// node's fields by index, as a struct or as words, matched the CPU in every tree.
layout(std430, binding = CLASSIFIER_NODES_BINDING) readonly buffer Nodes {
    ivec4 nodes[];
};
layout(std430, binding = CLASSIFIER_ROOTS_BINDING) readonly buffer Roots {
    int roots[];
};
uniform int treeCount;
uniform int maxDepth; // bounds each walk, whatever the buffer holds
// R16F, ceil(classifierDims / CLASSIFIER_PLACE_CELL) cells, cell c's texel centre at voxel
// c * cell + (cell - 1) / 2.
layout(binding = CLASSIFIER_PLACE_UNIT) uniform highp sampler3D classifierPlace;

float classifierPlaceAt(ivec3 v) {
    ivec3 cells = (classifierDims + CLASSIFIER_PLACE_CELL - 1) / CLASSIFIER_PLACE_CELL;
    vec3 at = (vec3(v) + 0.5) / (vec3(cells) * float(CLASSIFIER_PLACE_CELL));
    return textureLod(classifierPlace, at, 0.0).r;
}

// The forest's look at one feature vector: the mean over the trees of the leaf's value. Also
// walked alone over given features (speed/classifier_walk.comp, the numerics check's), so that a
// wrong walk and wrong features tell apart on a GPU. A walk written as an unbounded while over
// the node buffer was miscompiled by llvmpipe (only the first tree counted, and 50 times
// slower): the bounded for is what runs.
float classifierLook(ClassifierFeatureVector f) {
    float sum = 0.0;
    for (int t = 0; t < treeCount; ++t) {
        int n = roots[t];
        for (int depth = 0; depth < maxDepth; ++depth) {
            ivec4 node = nodes[n];
            if (node.x < 0) {
                break;
            }
            n = node.z + (classifierFeature(f, node.x) < intBitsToFloat(node.y) ? 0 : 1);
        }
        sum += intBitsToFloat(nodes[n].w);
    }
    return sum / float(treeCount);
}

float classifierSpeedAt(ivec3 v) {
    float look = classifierLook(classifierFeatures(v));
    return look + (1.0 - abs(look)) * classifierPlaceAt(v);
}
