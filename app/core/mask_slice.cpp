#include "core/mask_slice.hpp"

#include <algorithm>
#include <glm/vec2.hpp>
#include <stdexcept>

namespace steerseg {

namespace {

// The two in-plane axes of `axis`, lower first.
glm::ivec2 planeAxes(int axis) {
    return axis == 0 ? glm::ivec2(1, 2) : axis == 1 ? glm::ivec2(0, 2) : glm::ivec2(0, 1);
}

} // namespace

std::vector<std::uint8_t> maskPlane(const MaskRuns& mask, const glm::ivec3& dims, int axis,
                                    int index) {
    if (axis < 0 || axis > 2 || index < 0 || index >= dims[axis]) {
        throw std::invalid_argument("no such plane of the mask");
    }
    const glm::ivec2 uv = planeAxes(axis);
    const auto w = static_cast<std::size_t>(dims[uv.x]);
    const auto h = static_cast<std::size_t>(dims[uv.y]);
    std::vector<std::uint8_t> plane(w * h, 0);
    if (mask.runs.empty()) {
        return plane;
    }
    const auto nx = static_cast<std::uint64_t>(dims.x);
    const auto ny = static_cast<std::uint64_t>(dims.y);
    if (mask.voxels != nx * ny * static_cast<std::uint64_t>(dims.z)) {
        throw std::invalid_argument("a mask of another grid");
    }
    // Inside runs only. An axial plane is one contiguous stretch of the voxels, so only the
    // part of each run within it is visited; the others visit each inside voxel once.
    const std::uint64_t slab = nx * ny;
    const std::uint64_t lo = axis == 2 ? static_cast<std::uint64_t>(index) * slab : 0;
    const std::uint64_t hi = axis == 2 ? lo + slab : mask.voxels;
    std::uint64_t at = 0;
    for (std::size_t r = 0; r < mask.runs.size() && at < hi; ++r) {
        const std::uint64_t end = at + mask.runs[r];
        if (r % 2 == 1) {
            for (std::uint64_t v = std::max(at, lo); v < std::min(end, hi); ++v) {
                const glm::ivec3 p(static_cast<int>(v % nx), static_cast<int>((v / nx) % ny),
                                   static_cast<int>(v / slab));
                if (p[axis] == index) {
                    plane[static_cast<std::size_t>(p[uv.x]) +
                          w * static_cast<std::size_t>(p[uv.y])] = 1;
                }
            }
        }
        at = end;
    }
    return plane;
}

std::vector<MaskEdge> planeBoundary(const std::vector<std::uint8_t>& plane, const glm::ivec3& dims,
                                    int axis, int index) {
    const glm::ivec2 uv = planeAxes(axis);
    const int w = dims[uv.x];
    const int h = dims[uv.y];
    const auto in = [&](int u, int v) {
        return u >= 0 && v >= 0 && u < w && v < h &&
               plane[static_cast<std::size_t>(u) +
                     static_cast<std::size_t>(w) * static_cast<std::size_t>(v)] != 0;
    };
    const auto point = [&](double u, double v) {
        glm::dvec3 p(0.0);
        p[axis] = index;
        p[uv.x] = u;
        p[uv.y] = v;
        return p;
    };
    std::vector<MaskEdge> out;
    for (int v = 0; v < h; ++v) {
        for (int u = 0; u < w; ++u) {
            if (!in(u, v)) {
                continue;
            }
            // Each face of an inside voxel whose neighbour is outside.
            if (!in(u - 1, v)) {
                out.push_back({point(u - 0.5, v - 0.5), point(u - 0.5, v + 0.5)});
            }
            if (!in(u + 1, v)) {
                out.push_back({point(u + 0.5, v - 0.5), point(u + 0.5, v + 0.5)});
            }
            if (!in(u, v - 1)) {
                out.push_back({point(u - 0.5, v - 0.5), point(u + 0.5, v - 0.5)});
            }
            if (!in(u, v + 1)) {
                out.push_back({point(u - 0.5, v + 0.5), point(u + 0.5, v + 0.5)});
            }
        }
    }
    return out;
}

} // namespace steerseg
