#pragma once

#include "gpu/gl_handle.hpp"

#include <glm/glm.hpp>

namespace steerseg::speed {

// Throws std::invalid_argument (one line) unless kappa is a finite number > 0.
void validateKappa(float kappa);

// The edge speed's stopping factor g = 1 / (1 + (|grad I| / kappa)^2) of `intensity` (an
// R32F 3D texture of real units, usually the smoothed scan) as a new R32F texture
// (shaders/speed/edge_factor.comp). kappa in real units per voxel: the gradient at which g is
// 1/2. Needs a current context; restores the GL state it found.
gpu::Texture edgeFactor(GLuint intensity, const glm::ivec3& dims, float kappa);

} // namespace steerseg::speed
