#include "core/sample_phantom.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

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

// The phantom's tissue at a point in mm from voxel (0, 0, 0), without noise.
double tissueAt(double x, double y, double z, const glm::dvec3& lesionMm, double lesionRadius,
                double lesionIntensity) {
    double value = 20.0;
    if (ellipsoid(x, y, z, 64, 64, 72, 58, 60, 62) < 1.0) {
        value = 250.0;
    }
    if (ellipsoid(x, y, z, 64, 64, 72, 50, 52, 54) < 1.0) {
        value = 420.0;
    }
    // Two ventricles, mirrored left and right.
    if (ellipsoid(x, y, z, 52, 62, 76, 6, 16, 10) < 1.0 ||
        ellipsoid(x, y, z, 76, 62, 76, 6, 16, 10) < 1.0) {
        value = 120.0;
    }
    const glm::dvec3 d = glm::dvec3(x, y, z) - lesionMm;
    if (glm::dot(d, d) < lesionRadius * lesionRadius) {
        value = lesionIntensity;
    }
    return value;
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
    const glm::dvec3 lesionMm = glm::dvec3(lesion.i, lesion.j, lesion.k) * g.spacing;
    const auto tissue = [&](double x, double y, double z) {
        return tissueAt(x, y, z, lesionMm, lesion.radiusMm, lesion.intensity);
    };
    // A scanner's voxel is the mean of the tissue over its extent (the partial volume), not the
    // tissue at its centre: a phantom sampled at centres has boundaries that step a whole voxel
    // at a time, which the 3D view draws as terraces and rings and the level set follows into
    // facets. Voxels whose corners disagree are averaged over 4 x 4 x 4 points.
    constexpr int kSub = 4;
    // The tissue at every voxel corner, once: neighbouring voxels share them.
    const glm::ivec3 corners = g.dims + 1;
    std::vector<double> corner(static_cast<std::size_t>(corners.x) * corners.y * corners.z);
    for (int k = 0; k < corners.z; ++k) {
        for (int j = 0; j < corners.y; ++j) {
            for (int i = 0; i < corners.x; ++i) {
                const glm::dvec3 p = (glm::dvec3(i, j, k) - 0.5) * g.spacing;
                corner[(static_cast<std::size_t>(k) * corners.y + j) * corners.x + i] =
                    tissue(p.x, p.y, p.z);
            }
        }
    }
    const auto cornerAt = [&](int i, int j, int k) {
        return corner[(static_cast<std::size_t>(k) * corners.y + j) * corners.x + i];
    };
    for (int k = 0; k < g.dims.z; ++k) {
        // Work in mm so the shapes are round in the world, not in voxels.
        const double z = k * g.spacing.z;
        for (int j = 0; j < g.dims.y; ++j) {
            const double y = j * g.spacing.y;
            for (int i = 0; i < g.dims.x; ++i) {
                const double x = i * g.spacing.x;
                double value = tissue(x, y, z);
                bool boundary = false;
                for (int n = 0; n < 8 && !boundary; ++n) {
                    boundary = cornerAt(i + (n & 1), j + ((n >> 1) & 1), k + (n >> 2)) != value;
                }
                if (boundary) {
                    double sum = 0.0;
                    for (int s = 0; s < kSub * kSub * kSub; ++s) {
                        const glm::dvec3 f =
                            (glm::dvec3(s % kSub, (s / kSub) % kSub, s / (kSub * kSub)) + 0.5) /
                                double(kSub) -
                            0.5;
                        sum += tissue(x + f.x * g.spacing.x, y + f.y * g.spacing.y,
                                      z + f.z * g.spacing.z);
                    }
                    value = sum / double(kSub * kSub * kSub);
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
