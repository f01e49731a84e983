#pragma once

// Voxel regions on a scan's grid for bench/accuracy_bound: 6-connectivity and growth, on
// flat masks (1 in, 0 out; i fastest).
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace steerseg::bench {

// The grid's voxels as flat indices and back, and their 6 face neighbours.
struct Grid {
    glm::ivec3 d;
    [[nodiscard]] std::size_t count() const {
        return static_cast<std::size_t>(d.x) * static_cast<std::size_t>(d.y) *
               static_cast<std::size_t>(d.z);
    }
    [[nodiscard]] glm::ivec3 at(std::size_t v) const {
        const auto sx = static_cast<std::size_t>(d.x);
        const auto sxy = sx * static_cast<std::size_t>(d.y);
        return {static_cast<int>(v % sx),
                static_cast<int>((v / sx) % static_cast<std::size_t>(d.y)),
                static_cast<int>(v / sxy)};
    }
    template <typename F> void forEachNeighbour(std::size_t v, F&& f) const {
        const glm::ivec3 p = at(v);
        const auto sx = static_cast<std::size_t>(d.x);
        const auto sxy = sx * static_cast<std::size_t>(d.y);
        if (p.x > 0) {
            f(v - 1);
        }
        if (p.x + 1 < d.x) {
            f(v + 1);
        }
        if (p.y > 0) {
            f(v - sx);
        }
        if (p.y + 1 < d.y) {
            f(v + sx);
        }
        if (p.z > 0) {
            f(v - sxy);
        }
        if (p.z + 1 < d.z) {
            f(v + sxy);
        }
    }
};

// The voxels of `allowed` 6-connected to a seed voxel that is itself allowed.
std::vector<std::uint8_t> connectedToSeeds(const Grid& g, const std::vector<std::uint8_t>& allowed,
                                           const std::vector<glm::ivec3>& seedVoxels);

// `mask` grown by `ring` 6-neighbour steps (a city-block ball).
std::vector<std::uint8_t> dilated(const Grid& g, const std::vector<std::uint8_t>& mask, int ring);

} // namespace steerseg::bench
