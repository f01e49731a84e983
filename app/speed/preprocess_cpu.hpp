#pragma once

// The CPU twins of the speed's preprocessing on the GPU: the anisotropic diffusion
// (shaders/speed/diffuse.comp, speed/smoothing) and the edge-stopping factor
// (shaders/speed/edge_factor.comp, speed/edge_factor), statement for statement in single
// precision, for the numerics check and the tests to hold the GPU's textures against. Plain
// loops over the whole scan: meant for small scans. GL-free.
#include "speed/smoothing_params.hpp"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace steerseg::speed {

// `intensities` after params.iterations diffusion steps (a copy when 0), i fastest. Throws
// std::invalid_argument for sizes that disagree or parameters validateSmoothing refuses.
std::vector<float> cpuSmoothScan(std::span<const float> intensities, const glm::ivec3& dims,
                                 const SmoothingParams& params);

// g = 1 / (1 + (|grad I| / kappa)^2) at every voxel. Throws std::invalid_argument for sizes that
// disagree or a kappa validateKappa refuses.
std::vector<float> cpuEdgeFactor(std::span<const float> intensities, const glm::ivec3& dims,
                                 float kappa);

} // namespace steerseg::speed
