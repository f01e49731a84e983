#include "core/mask_box.hpp"

#include "core/volume.hpp"

#include <stdexcept>
#include <string>

namespace steerseg {

std::optional<MaskBox> maskBox(const glm::ivec3& dims, std::span<const std::uint8_t> mask) {
    const std::size_t voxels = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                               static_cast<std::size_t>(dims.z);
    if (mask.size() != voxels) {
        throw std::invalid_argument("a mask of " + std::to_string(mask.size()) +
                                    " voxels on a grid of " + std::to_string(voxels));
    }
    glm::ivec3 lo(dims);
    glm::ivec3 hi(-1);
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            const std::uint8_t* row = mask.data() + linearIndex(dims, 0, j, k);
            for (int i = 0; i < dims.x; ++i) {
                if (row[i] != 0) {
                    lo = glm::min(lo, glm::ivec3(i, j, k));
                    hi = glm::max(hi, glm::ivec3(i, j, k));
                }
            }
        }
    }
    if (hi.x < 0) {
        return std::nullopt;
    }
    return MaskBox{lo, hi};
}

MaskBox grownWithin(const MaskBox& box, int margin, const glm::ivec3& dims) {
    return {glm::max(box.lo - margin, glm::ivec3(0)), glm::min(box.hi + margin, dims - 1)};
}

} // namespace steerseg
