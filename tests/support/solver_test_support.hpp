#pragma once

// Shared helpers of the solver tests: synthetic volumes and mask comparisons.

#include "core/mask_overlap.hpp"
#include "model/level_set_params.hpp"

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <numbers>
#include <span>
#include <vector>

namespace steerseg::test {

inline std::size_t voxelIndex(const glm::ivec3& d, int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(d.x) *
               (static_cast<std::size_t>(j) +
                static_cast<std::size_t>(d.y) * static_cast<std::size_t>(k));
}

inline std::size_t countOf(const glm::ivec3& d) {
    return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
           static_cast<std::size_t>(d.z);
}

// A volume of `background` with a ball of `value` (centre, radius in voxels).
inline std::vector<float> ballVolume(const glm::ivec3& d, float background, float value,
                                     glm::vec3 centre, float radius) {
    std::vector<float> v(countOf(d), background);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                if (glm::length(glm::vec3(i, j, k) - centre) <= radius) {
                    v[voxelIndex(d, i, j, k)] = value;
                }
            }
        }
    }
    return v;
}

// ballVolume's ball of 1 in 0 with a deterministic ripple of +-0.15, so that a front's speed
// varies voxel by voxel and its parts stop at different times.
inline std::vector<float> rippledBallVolume(const glm::ivec3& d, glm::vec3 centre, float radius) {
    std::vector<float> v = ballVolume(d, 0.0F, 1.0F, centre, radius);
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                v[voxelIndex(d, i, j, k)] +=
                    0.15F * std::sin(0.9F * static_cast<float>(i) + 1.7F * static_cast<float>(j) +
                                     0.6F * static_cast<float>(k));
            }
        }
    }
    return v;
}

// The window the rippled ball's tests grow it with: the ball's 1 +- 0.6, so the ripple changes
// the speed voxel by voxel but not its sign.
inline model::LevelSetParams rippledBallParams() {
    model::LevelSetParams p;
    p.T = 1.0F;
    p.eps = 0.6F;
    p.alpha = 0.7F;
    return p;
}

inline std::size_t insideCount(std::span<const std::uint8_t> mask) {
    std::size_t n = 0;
    for (std::uint8_t m : mask) {
        n += m != 0 ? 1 : 0;
    }
    return n;
}

inline double dice(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
    std::size_t both = 0;
    std::size_t sum = 0;
    for (std::size_t n = 0; n < a.size(); ++n) {
        both += (a[n] != 0 && b[n] != 0) ? 1 : 0;
        sum += (a[n] != 0 ? 1 : 0) + (b[n] != 0 ? 1 : 0);
    }
    return sum == 0 ? 1.0 : 2.0 * static_cast<double>(both) / static_cast<double>(sum);
}

// Radius of the ball with the mask's volume.
inline double equivalentRadius(std::span<const std::uint8_t> mask) {
    return std::cbrt(3.0 * static_cast<double>(insideCount(mask)) / (4.0 * std::numbers::pi));
}

} // namespace steerseg::test
