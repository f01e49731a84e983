#include "core/sample_phantom.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace steerseg {

namespace {

// Counter-based hash noise: the same voxel always gets the same value on every machine, so
// golden outputs stay stable (no std::normal_distribution, whose output is library-defined).
double hashNoise(std::uint32_t n) {
    double sum = 0.0;
    for (std::uint32_t round = 0; round < 4; ++round) {
        std::uint32_t x = n * 4u + round;
        x ^= x >> 16;
        x *= 0x7feb352dU;
        x ^= x >> 15;
        x *= 0x846ca68bU;
        x ^= x >> 16;
        sum += static_cast<double>(x) / 4294967295.0;
    }
    // Irwin-Hall: sum of 4 uniforms has variance 4/12; scale to unit variance.
    return (sum - 2.0) / std::sqrt(4.0 / 12.0);
}

double ellipsoid(double x, double y, double z, double cx, double cy, double cz, double rx,
                 double ry, double rz) {
    const double dx = (x - cx) / rx;
    const double dy = (y - cy) / ry;
    const double dz = (z - cz) / rz;
    return dx * dx + dy * dy + dz * dz; // < 1 inside
}

} // namespace

Volume makeSamplePhantom() {
    Geometry g;
    g.dims = {128, 128, 96};
    g.spacing = {1.0, 1.0, 1.5};
    // Centre the phantom on the world origin, LPS axes.
    g.origin = -0.5 * g.spacing * glm::dvec3(g.dims - 1);
    Volume v(VoxelType::UInt16, g);
    auto out = v.voxels<std::uint16_t>();
    const PhantomLesion lesion = kPhantomLesion;
    for (int k = 0; k < g.dims.z; ++k) {
        // Work in mm so the shapes are round in the world, not in voxels.
        const double z = k * g.spacing.z;
        for (int j = 0; j < g.dims.y; ++j) {
            const double y = j * g.spacing.y;
            for (int i = 0; i < g.dims.x; ++i) {
                const double x = i * g.spacing.x;
                double value = 20.0;
                const double head = ellipsoid(x, y, z, 64, 64, 72, 58, 60, 62);
                if (head < 1.0) {
                    value = 250.0;
                }
                const double brain = ellipsoid(x, y, z, 64, 64, 72, 50, 52, 54);
                if (brain < 1.0) {
                    value = 420.0;
                }
                // Two ventricles, mirrored left and right.
                if (ellipsoid(x, y, z, 52, 62, 76, 6, 16, 10) < 1.0 ||
                    ellipsoid(x, y, z, 76, 62, 76, 6, 16, 10) < 1.0) {
                    value = 120.0;
                }
                const double lx = (i - lesion.i) * g.spacing.x;
                const double ly = (j - lesion.j) * g.spacing.y;
                const double lz = (k - lesion.k) * g.spacing.z;
                const double r = lesion.radiusMm;
                if (lx * lx + ly * ly + lz * lz < r * r) {
                    value = lesion.intensity;
                }
                const std::size_t n = v.linearIndex(i, j, k);
                value += 15.0 * hashNoise(static_cast<std::uint32_t>(n));
                out[n] = static_cast<std::uint16_t>(std::clamp(std::lround(value), 0L, 65535L));
            }
        }
    }
    return v;
}

} // namespace steerseg
