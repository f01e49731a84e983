#pragma once

// The CPU twin of shaders/speed/classifier_features.glsl: the classifier's per-voxel features
// from host intensities, in single precision and in the shader's order of operations, so that
// they equal what a correct GPU computes to float rounding (bit for bit on llvmpipe). The
// training's features come from here where the scan is on the host (issue 47: a driver that
// returned another sample's gathered features trained the forest on the wrong tissue), and the
// numerics check and the tests hold the GPU's gather and evaluation against it. GL-free.
#include "core/volume.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// Features per voxel (shaders/speed/classifier_layout.h): intensity; mean 3x3x3, 5x5x5 and
// 9x9x9 (every second voxel); standard deviation over the same three; gradient magnitude of the
// 3x3x3 mean. The windows step `stride` voxels along each axis.
inline constexpr int kClassifierFeatureCount = 8;

// The windows' step along an axis is about this many mm: in voxel steps, a series of 0.3 mm
// pixels has windows a third as wide across the tissue as on the 1 mm scans they were made on,
// and a first session's forest drew less of the structure the finer the grid (docs/speed.md).
inline constexpr double kClassifierFeatureStepMm = 1.0;

// The step per axis: round(kClassifierFeatureStepMm / spacing), at least 1 (an axis of 0.67 mm
// or coarser keeps voxel steps) and at most 16; 1 where the spacing is not a positive number.
glm::ivec3 classifierFeatureStride(const glm::dvec3& spacing);

// One row of kClassifierFeatureCount values per voxel, in the order given, from real-unit
// intensities (i fastest) of `dims`. Throws std::invalid_argument when the sizes disagree, a
// voxel lies outside the scan or a stride is below 1.
std::vector<float> cpuClassifierFeatures(std::span<const float> intensities, glm::ivec3 dims,
                                         std::span<const glm::ivec3> voxels,
                                         glm::ivec3 stride = glm::ivec3(1));
// The same from a scan's real values, as gpu::ScanTexture uploads them (float of the rescaled
// stored value), without a float copy of the whole scan.
std::vector<float> cpuClassifierFeatures(const Volume& scan, std::span<const glm::ivec3> voxels,
                                         glm::ivec3 stride = glm::ivec3(1));

} // namespace steerseg::speed
