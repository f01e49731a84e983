#include "bench/accuracy/voxel_regions.hpp"

#include "core/volume.hpp"

namespace steerseg::bench {

std::vector<std::uint8_t> connectedToSeeds(const Grid& g, const std::vector<std::uint8_t>& allowed,
                                           const std::vector<glm::ivec3>& seedVoxels) {
    std::vector<std::uint8_t> out(g.count(), 0);
    std::vector<std::size_t> stack;
    for (const glm::ivec3& s : seedVoxels) {
        const std::size_t v = linearIndex(g.d, s.x, s.y, s.z);
        if (allowed[v] != 0 && out[v] == 0) {
            out[v] = 1;
            stack.push_back(v);
        }
    }
    while (!stack.empty()) {
        const std::size_t v = stack.back();
        stack.pop_back();
        g.forEachNeighbour(v, [&](std::size_t n) {
            if (allowed[n] != 0 && out[n] == 0) {
                out[n] = 1;
                stack.push_back(n);
            }
        });
    }
    return out;
}

std::vector<std::uint8_t> dilated(const Grid& g, const std::vector<std::uint8_t>& mask, int ring) {
    std::vector<std::uint8_t> out = mask;
    std::vector<std::size_t> front;
    for (std::size_t v = 0; v < mask.size(); ++v) {
        if (mask[v] != 0) {
            front.push_back(v);
        }
    }
    for (int step = 0; step < ring; ++step) {
        std::vector<std::size_t> next;
        for (const std::size_t v : front) {
            g.forEachNeighbour(v, [&](std::size_t n) {
                if (out[n] == 0) {
                    out[n] = 1;
                    next.push_back(n);
                }
            });
        }
        front = std::move(next);
    }
    return out;
}

} // namespace steerseg::bench
