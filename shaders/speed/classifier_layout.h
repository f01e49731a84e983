// The classifier's feature vector, shared by its shaders and the C++ that reads what they gather
// (include path shaders/). Only comments, #define and include guards, so that the file is valid
// GLSL ES 3.10 and C++.
#ifndef STEERSEG_SHADERS_SPEED_CLASSIFIER_LAYOUT_H
#define STEERSEG_SHADERS_SPEED_CLASSIFIER_LAYOUT_H

// Per voxel, in this order (speed/classifier_features.glsl):
//   0 intensity, 1 mean 3x3x3, 2 mean 5x5x5, 3 mean 9x9x9 (every second voxel),
//   4 std 3x3x3, 5 std 5x5x5, 6 std 9x9x9 (every second voxel),
//   7 gradient magnitude (central differences of the 3x3x3 mean)
#define CLASSIFIER_FEATURE_COUNT 8

// Voxels a side of a cell of the place vote's grid (speed/place_vote.hpp, kPlaceVoteCell).
#define CLASSIFIER_PLACE_CELL 4

#endif
