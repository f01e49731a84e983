#pragma once

// The classifier's per-voxel features at chosen voxels, computed on the GPU by the code the
// evaluation runs (shaders/speed/classifier_features.glsl). Needs a current GLES 3.1 context.
#include "gpu/gl.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// Features per voxel (shaders/speed/classifier_layout.h): intensity; mean 3x3x3, 5x5x5 and
// 9x9x9 (every second voxel); standard deviation over the same three; gradient magnitude of the
// 3x3x3 mean.
inline constexpr int kClassifierFeatureCount = 8;

// Checks that `intensity` is an R32F 3D texture of `dims`; throws std::invalid_argument if not.
void checkIntensityTexture(GLuint intensity, glm::ivec3 dims);

// One row of kClassifierFeatureCount values per voxel, in the order given. `intensity`: an R32F
// 3D texture of `dims` (texelFetch only). Voxels must lie in the scan.
std::vector<float> gatherClassifierFeatures(GLuint intensity, glm::ivec3 dims,
                                            std::span<const glm::ivec3> voxels);

} // namespace steerseg::speed
