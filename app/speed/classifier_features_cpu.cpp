#include "speed/classifier_features_cpu.hpp"

#include "core/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace steerseg::speed {

namespace {

constexpr double kMaxFeatureStride = 16.0;

// classifierFeatures() of classifier_features.glsl, statement for statement: the same sums in
// the same order, float throughout (a double here would differ from every GPU's answer).
template <typename Fetch>
void featuresAt(const Fetch& fetchLinear, glm::ivec3 dims, glm::ivec3 stride, glm::ivec3 v,
                float* f) {
    const auto fetch = [&](glm::ivec3 p) {
        const glm::ivec3 c = glm::clamp(p, glm::ivec3(0), dims - 1);
        return fetchLinear(linearIndex(dims, c.x, c.y, c.z));
    };
    const float centre = fetch(v);
    float s3 = 0.0F;
    float q3 = 0.0F;
    float s5 = 0.0F;
    float q5 = 0.0F;
    glm::vec3 g(0.0F);
    for (int dz = -2; dz <= 2; ++dz) {
        for (int dy = -2; dy <= 2; ++dy) {
            for (int dx = -2; dx <= 2; ++dx) {
                const glm::ivec3 a = glm::abs(glm::ivec3(dx, dy, dz));
                const float d = fetch(v + glm::ivec3(dx, dy, dz) * stride) - centre;
                s5 += d;
                q5 += d * d;
                if (a.x <= 1 && a.y <= 1 && a.z <= 1) {
                    s3 += d;
                    q3 += d * d;
                }
                if (a.y <= 1 && a.z <= 1) {
                    g.x += static_cast<float>((dx > 0) - (dx < 0)) * d;
                }
                if (a.x <= 1 && a.z <= 1) {
                    g.y += static_cast<float>((dy > 0) - (dy < 0)) * d;
                }
                if (a.x <= 1 && a.y <= 1) {
                    g.z += static_cast<float>((dz > 0) - (dz < 0)) * d;
                }
            }
        }
    }
    float s9 = 0.0F;
    float q9 = 0.0F;
    for (int dz = -4; dz <= 4; dz += 2) {
        for (int dy = -4; dy <= 4; dy += 2) {
            for (int dx = -4; dx <= 4; dx += 2) {
                const float d = fetch(v + glm::ivec3(dx, dy, dz) * stride) - centre;
                s9 += d;
                q9 += d * d;
            }
        }
    }
    const float m3 = s3 / 27.0F;
    const float m5 = s5 / 125.0F;
    const float m9 = s9 / 125.0F;
    f[0] = centre;
    f[1] = centre + m3;
    f[2] = centre + m5;
    f[3] = centre + m9;
    f[4] = std::sqrt(std::max(q3 / 27.0F - m3 * m3, 0.0F));
    f[5] = std::sqrt(std::max(q5 / 125.0F - m5 * m5, 0.0F));
    f[6] = std::sqrt(std::max(q9 / 125.0F - m9 * m9, 0.0F));
    // length(g) summed as llvmpipe sums it (x, then y and z together): bit for bit there, and
    // within a rounding of any other order.
    f[7] = std::sqrt(g.x * g.x + (g.y * g.y + g.z * g.z)) * (0.5F / 27.0F);
}

template <typename Fetch>
std::vector<float> featuresOf(const Fetch& fetchLinear, glm::ivec3 dims, glm::ivec3 stride,
                              std::span<const glm::ivec3> voxels) {
    if (glm::any(glm::lessThan(stride, glm::ivec3(1)))) {
        throw std::invalid_argument("classifier features: a stride below one voxel");
    }
    for (const glm::ivec3 v : voxels) {
        if (glm::any(glm::lessThan(v, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(v, dims))) {
            throw std::invalid_argument("classifier speed: a sample voxel lies outside the scan");
        }
    }
    // A correction's retraining reads 250 voxels for each of its samples (40,000 by default):
    // on every core, each piece writing only its own rows.
    std::vector<float> out(voxels.size() * kClassifierFeatureCount);
    constexpr std::size_t kPiece = 2048;
    parallelFor((voxels.size() + kPiece - 1) / kPiece, [&](std::size_t piece) {
        const std::size_t end = std::min(voxels.size(), (piece + 1) * kPiece);
        for (std::size_t n = piece * kPiece; n < end; ++n) {
            featuresAt(fetchLinear, dims, stride, voxels[n],
                       out.data() + n * kClassifierFeatureCount);
        }
    });
    return out;
}

} // namespace

glm::ivec3 classifierFeatureStride(const glm::dvec3& spacing) {
    glm::ivec3 stride(1);
    for (int a = 0; a < 3; ++a) {
        const double steps = kClassifierFeatureStepMm / spacing[a];
        if (std::isfinite(steps) && steps > 0.0) {
            stride[a] = static_cast<int>(std::clamp(std::round(steps), 1.0, kMaxFeatureStride));
        }
    }
    return stride;
}

std::vector<float> cpuClassifierFeatures(std::span<const float> intensities, glm::ivec3 dims,
                                         std::span<const glm::ivec3> voxels, glm::ivec3 stride) {
    if (glm::any(glm::lessThan(dims, glm::ivec3(1))) ||
        intensities.size() != static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                                  static_cast<std::size_t>(dims.z)) {
        throw std::invalid_argument("classifier features: the intensities do not fill the scan");
    }
    return featuresOf([&](std::size_t n) { return intensities[n]; }, dims, stride, voxels);
}

std::vector<float> cpuClassifierFeatures(const Volume& scan, std::span<const glm::ivec3> voxels,
                                         glm::ivec3 stride) {
    // The stored type chosen once, not at each of the 250 fetches a sample makes: the value is
    // Volume::realAt's, as gpu::ScanTexture uploads it.
    const Rescale r = scan.rescale();
    const auto from = [&]<typename T>(std::span<const T> stored) {
        return featuresOf(
            [&](std::size_t n) {
                return static_cast<float>(r.apply(static_cast<double>(stored[n])));
            },
            scan.dims(), stride, voxels);
    };
    switch (scan.type()) {
    case VoxelType::UInt8:
        return from(scan.voxels<std::uint8_t>());
    case VoxelType::Int16:
        return from(scan.voxels<std::int16_t>());
    case VoxelType::UInt16:
        return from(scan.voxels<std::uint16_t>());
    case VoxelType::Float32:
        break;
    }
    return from(scan.voxels<float>());
}

} // namespace steerseg::speed
