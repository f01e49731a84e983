#pragma once

// The CPU twin of the classifier speed's evaluation (shaders/speed/classifier_forest.glsl's
// classifierSpeedAt): the forest over a voxel's features, then the marks' vote where the forest
// is unsure. GL-free.
#include "speed/place_vote.hpp"
#include "speed/random_forest.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// look + (1 - |look|) place: the forest's look, and the vote of the marks near the voxel where
// it is unsure.
float classifierSpeedFrom(float look, float place);

// The forest's look at each feature row (kClassifierFeatureCount values a row): the twin of
// ClassifierSpeed::walkOnGpu. Throws std::invalid_argument for rows of the wrong length.
std::vector<float> cpuForestLooks(const RandomForest& forest, std::span<const float> features);

// The speed at each voxel from its feature row (kClassifierFeatureCount values per voxel, in
// the order of `voxels`: cpuClassifierFeatures). Throws std::invalid_argument when the sizes
// disagree.
std::vector<float> cpuClassifierSpeed(const RandomForest& forest, const PlaceVote& vote,
                                      std::span<const float> features,
                                      std::span<const glm::ivec3> voxels);

} // namespace steerseg::speed
