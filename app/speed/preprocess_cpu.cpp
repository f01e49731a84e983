#include "speed/preprocess_cpu.hpp"

#include "core/volume.hpp"
#include "speed/edge_factor.hpp"
#include "speed/smoothing_params.hpp"

#include <cmath>
#include <stdexcept>

namespace steerseg::speed {

namespace {

void checkSize(std::span<const float> intensities, const glm::ivec3& dims) {
    if (glm::any(glm::lessThan(dims, glm::ivec3(1))) ||
        intensities.size() != static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                                  static_cast<std::size_t>(dims.z)) {
        throw std::invalid_argument("speed preprocessing: the intensities do not fill the scan");
    }
}

// The shaders' at(): borders repeat the edge voxel.
float at(std::span<const float> v, const glm::ivec3& dims, glm::ivec3 p) {
    const glm::ivec3 c = glm::clamp(p, glm::ivec3(0), dims - 1);
    return v[linearIndex(dims, c.x, c.y, c.z)];
}

// Every voxel in raster order (i fastest), as the output is laid out.
template <typename Each> void forEachVoxel(const glm::ivec3& dims, const Each& each) {
    std::size_t n = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i, ++n) {
                each(n, glm::ivec3(i, j, k));
            }
        }
    }
}

} // namespace

std::vector<float> cpuSmoothScan(std::span<const float> intensities, const glm::ivec3& dims,
                                 const SmoothingParams& params) {
    checkSize(intensities, dims);
    validateSmoothing(params);
    std::vector<float> source(intensities.begin(), intensities.end());
    std::vector<float> target(source.size());
    const float invConductance = 1.0F / params.conductance;
    for (int step = 0; step < params.iterations; ++step) {
        forEachVoxel(dims, [&](std::size_t n, glm::ivec3 v) {
            const float c = source[n];
            const auto flux = [&](glm::ivec3 e) {
                const float d = at(source, dims, v + e) - c;
                const float s = d * invConductance;
                return std::exp(-s * s) * d;
            };
            const float sum = flux({1, 0, 0}) + flux({-1, 0, 0}) + flux({0, 1, 0}) +
                              flux({0, -1, 0}) + flux({0, 0, 1}) + flux({0, 0, -1});
            target[n] = c + kDiffusionTimeStep * sum;
        });
        source.swap(target);
    }
    return source;
}

std::vector<float> cpuEdgeFactor(std::span<const float> intensities, const glm::ivec3& dims,
                                 float kappa) {
    checkSize(intensities, dims);
    validateKappa(kappa);
    std::vector<float> out(intensities.size());
    const float invKappa = 1.0F / kappa;
    forEachVoxel(dims, [&](std::size_t n, glm::ivec3 v) {
        const auto diff = [&](glm::ivec3 e) {
            return 0.5F * (at(intensities, dims, v + e) - at(intensities, dims, v - e));
        };
        const glm::vec3 g(diff({1, 0, 0}), diff({0, 1, 0}), diff({0, 0, 1}));
        const float s = std::sqrt(g.x * g.x + g.y * g.y + g.z * g.z) * invKappa;
        out[n] = 1.0F / (1.0F + s * s);
    });
    return out;
}

} // namespace steerseg::speed
