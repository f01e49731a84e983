#pragma once

// The classifier's per-voxel features at chosen voxels, computed on the GPU by the code the
// evaluation runs (shaders/speed/classifier_features.glsl). Needs a current GLES 3.1 context.
#include "gpu/gl.hpp"
#include "speed/classifier_features_cpu.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// Checks that `intensity` is an R32F 3D texture of `dims`; throws std::invalid_argument if not.
void checkIntensityTexture(GLuint intensity, glm::ivec3 dims);

// One row of kClassifierFeatureCount values per voxel, in the order given. `intensity`: an R32F
// 3D texture of `dims` (texelFetch only). Voxels must lie in the scan. The rows start as NaN, so
// a row the GPU did not write cannot pass for features: throws GpuNumericsError naming how many.
// The windows step `stride` voxels (classifierFeatureStride).
std::vector<float> gatherClassifierFeatures(GLuint intensity, glm::ivec3 dims,
                                            std::span<const glm::ivec3> voxels,
                                            glm::ivec3 stride = glm::ivec3(1));

} // namespace steerseg::speed
