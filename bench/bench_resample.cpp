#include "bench/bench_scan.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::bench {

Volume resampled(const Volume& scan, double factor) {
    if (!(factor > 0.0) || factor > 8.0) {
        throw std::runtime_error("resample factor must be in (0, 8]");
    }
    Geometry g = scan.geometry();
    const glm::ivec3 from = g.dims;
    g.dims = glm::max(glm::ivec3(glm::round(glm::dvec3(from) * factor)), glm::ivec3(1));
    // Same world extent: voxel centres at the ends stay where they were.
    const glm::dvec3 step = glm::dvec3(from - 1) / glm::max(glm::dvec3(g.dims - 1), glm::dvec3(1));
    g.spacing *= step;
    Volume out(VoxelType::Float32, g);
    out.setRescale({1.0, 0.0});
    auto dst = out.voxels<float>();
    const auto at = [&](int i, int j, int k) {
        return scan.valueAt(std::clamp(i, 0, from.x - 1), std::clamp(j, 0, from.y - 1),
                            std::clamp(k, 0, from.z - 1));
    };
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::dvec3 p = glm::dvec3(i, j, k) * step;
                const glm::ivec3 p0(glm::floor(p));
                const glm::dvec3 f = p - glm::dvec3(p0);
                double v = 0.0;
                for (int c = 0; c < 8; ++c) {
                    const glm::ivec3 o(c & 1, (c >> 1) & 1, (c >> 2) & 1);
                    const double w = (o.x != 0 ? f.x : 1.0 - f.x) * (o.y != 0 ? f.y : 1.0 - f.y) *
                                     (o.z != 0 ? f.z : 1.0 - f.z);
                    if (w > 0.0) {
                        v += w * at(p0.x + o.x, p0.y + o.y, p0.z + o.z);
                    }
                }
                dst[out.linearIndex(i, j, k)] = static_cast<float>(v);
            }
        }
    }
    return out;
}

} // namespace steerseg::bench
