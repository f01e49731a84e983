#pragma once

#include "gpu/gl.hpp"

#include <cstdint>
#include <glm/glm.hpp>

namespace steerseg::solver {

// Host mirror of shaders/common/brick_pool.glsl: what a reader of the level set (the renderer,
// tests) needs to bind to read phi straight from the solver's pool. Valid until the solver's
// next step or edit (the pool may be reallocated).
struct BrickPoolView {
    GLuint pageTableBuffer = 0; // uint per brick
    GLuint phiPoolBuffer = 0;   // float per pooled voxel (current iteration)
    glm::ivec3 volumeDims{0};
    glm::ivec3 brickGrid{0};
    int brickSize = 0;
    float phiFar = 0.0F;
};

inline constexpr std::uint32_t kBrickInside = 0xFFFFFFFEu;
inline constexpr std::uint32_t kBrickOutside = 0xFFFFFFFFu;

} // namespace steerseg::solver
