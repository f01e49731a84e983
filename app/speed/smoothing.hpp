#pragma once

#include "gpu/gl_handle.hpp"
#include "speed/smoothing_params.hpp"

#include <functional>
#include <glm/glm.hpp>

namespace steerseg::speed {

// Called after each iteration with (done, total).
using SmoothingProgress = std::function<void(int done, int total)>;

// The smoothed copy of `scan` (an R32F 3D texture of real units, dims), as a new R32F texture;
// an empty texture when params.iterations = 0. Ping-pongs two textures and frees the partner
// before returning, so the peak is two extra scan-sized float textures. Needs a current
// context; restores the GL state it found.
gpu::Texture smoothScan(GLuint scan, const glm::ivec3& dims, const SmoothingParams& params,
                        const SmoothingProgress& progress = {});

} // namespace steerseg::speed
