#include "core/mask_field.hpp"

#include "core/mask_box.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace steerseg {

namespace {

// The blur of maskToField: a Gaussian of one voxel, cut at three, along each index axis.
constexpr int kBlurRadius = 3;
constexpr double kBlurSigma = 1.0;
// How far from zero a voxel is held on its own side, so no crossing lands on a voxel centre.
constexpr float kHeldOff = 1e-3f;

std::array<float, 2 * kBlurRadius + 1> blurWeights() {
    std::array<float, 2 * kBlurRadius + 1> w{};
    double sum = 0.0;
    for (int d = -kBlurRadius; d <= kBlurRadius; ++d) {
        sum += std::exp(-0.5 * d * d / (kBlurSigma * kBlurSigma));
    }
    for (int d = -kBlurRadius; d <= kBlurRadius; ++d) {
        w[static_cast<std::size_t>(d + kBlurRadius)] =
            static_cast<float>(std::exp(-0.5 * d * d / (kBlurSigma * kBlurSigma)) / sum);
    }
    return w;
}

} // namespace

std::vector<float> maskToField(const Geometry& geometry, std::span<const std::uint8_t> mask) {
    if (mask.size() != geometry.voxelCount()) {
        throw std::invalid_argument("the mask has " + std::to_string(mask.size()) +
                                    " voxels for a grid of " +
                                    std::to_string(geometry.voxelCount()));
    }
    const glm::ivec3 dims = geometry.dims;
    // Farther than the blur's reach from every inside voxel the field is exactly +0.5, so only
    // the mask's box grown by that reach is blurred.
    const std::optional<MaskBox> inside = maskBox(dims, mask);
    std::vector<float> field(mask.size(), 0.5f);
    if (!inside) {
        return field;
    }
    const MaskBox blurred = grownWithin(*inside, kBlurRadius, dims);
    const glm::ivec3 lo = blurred.lo;
    const glm::ivec3 box = boxDims(blurred);
    std::vector<float> a = cropMask(dims, mask, blurred, -0.5f, 0.5f);
    // One axis at a time; beyond the box (in the grid or past it) every pass sees +0.5.
    const auto weights = blurWeights();
    std::vector<float> b(a.size());
    for (int axis = 0; axis < 3; ++axis) {
        glm::ivec3 unit(0);
        unit[axis] = 1;
        const auto stride = static_cast<std::ptrdiff_t>(linearIndex(box, unit.x, unit.y, unit.z));
        for (int k = 0; k < box.z; ++k) {
            for (int j = 0; j < box.y; ++j) {
                for (int i = 0; i < box.x; ++i) {
                    const glm::ivec3 p(i, j, k);
                    const std::size_t at = linearIndex(box, i, j, k);
                    float sum = 0.0f;
                    for (int d = -kBlurRadius; d <= kBlurRadius; ++d) {
                        const int q = p[axis] + d;
                        const float v = q < 0 || q >= box[axis]
                                            ? 0.5f
                                            : a[static_cast<std::size_t>(
                                                  static_cast<std::ptrdiff_t>(at) + d * stride)];
                        sum += weights[static_cast<std::size_t>(d + kBlurRadius)] * v;
                    }
                    b[at] = sum;
                }
            }
        }
        a.swap(b);
    }
    for (int k = 0; k < box.z; ++k) {
        for (int j = 0; j < box.y; ++j) {
            for (int i = 0; i < box.x; ++i) {
                const std::size_t at = linearIndex(dims, lo.x + i, lo.y + j, lo.z + k);
                const float v = a[linearIndex(box, i, j, k)];
                field[at] = mask[at] != 0 ? std::min(v, -kHeldOff) : std::max(v, kHeldOff);
            }
        }
    }
    return field;
}

} // namespace steerseg
