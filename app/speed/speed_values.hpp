#pragma once

// The data term the solver steps with (shaders/speed/data_speed.glsl) evaluated at every voxel
// of a small scan, for the numerics check (session/numerics_check) and the tests: what a GPU
// computes for each kind, to be held against the CPU twin voxel for voxel.
#include "gpu/gl_handle.hpp"
#include "model/level_set_params.hpp"
#include "speed/speed_inputs.hpp"

#include <glm/glm.hpp>

namespace steerseg::speed {

// An R32F texture of `dims`: the data term of `inputs` (validated: std::invalid_argument) with
// `params`' T and eps, its intensity `rawScan` where inputs.intensity is 0. A classify speed must
// be complete (no forest on demand).
gpu::Texture speedValues(const SpeedInputs& inputs, GLuint rawScan, const glm::ivec3& dims,
                         const model::LevelSetParams& params);

} // namespace steerseg::speed
