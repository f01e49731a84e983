#include "core/mask_inside.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg {

namespace {

constexpr const char* kNanProblem = "is NaN; a mask's voxels must be numbers (non-zero = inside)";

std::string voxelText(const glm::ivec3& dims, std::size_t n) {
    const auto nx = static_cast<std::size_t>(dims.x);
    const auto ny = static_cast<std::size_t>(dims.y);
    return "(" + std::to_string(n % nx) + ", " + std::to_string(n / nx % ny) + ", " +
           std::to_string(n / (nx * ny)) + ")";
}

} // namespace

bool insideValue(double value) {
    if (std::isnan(value)) {
        throw std::invalid_argument(std::string("a voxel ") + kNanProblem);
    }
    return value != 0.0;
}

std::vector<std::uint8_t> maskInside(const Volume& mask) {
    std::vector<std::uint8_t> inside(mask.geometry().voxelCount());
    for (std::size_t n = 0; n < inside.size(); ++n) {
        const double value = mask.rescale().apply(mask.storedAt(n));
        if (std::isnan(value)) {
            throw std::invalid_argument("voxel " + voxelText(mask.dims(), n) + " " + kNanProblem);
        }
        inside[n] = insideValue(value) ? 1 : 0;
    }
    return inside;
}

} // namespace steerseg
