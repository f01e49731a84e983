#include "core/mask_runs.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace steerseg {

MaskRuns encodeRuns(std::span<const std::uint8_t> mask) {
    MaskRuns out;
    out.voxels = mask.size();
    bool inside = false;
    std::size_t n = 0;
    while (n < mask.size()) {
        std::size_t end = n;
        while (end < mask.size() && (mask[end] != 0) == inside &&
               end - n < std::numeric_limits<std::uint32_t>::max()) {
            ++end;
        }
        out.runs.push_back(static_cast<std::uint32_t>(end - n));
        n = end;
        inside = !inside;
    }
    return out;
}

std::vector<std::uint8_t> decodeRuns(const MaskRuns& runs) {
    std::vector<std::uint8_t> mask(runs.voxels, 0);
    std::size_t n = 0;
    bool inside = false;
    for (const std::uint32_t length : runs.runs) {
        if (length > runs.voxels - n) {
            throw std::invalid_argument("mask runs add up to more than the mask's voxels");
        }
        if (inside) {
            std::fill_n(mask.begin() + static_cast<std::ptrdiff_t>(n), length, std::uint8_t{1});
        }
        n += length;
        inside = !inside;
    }
    if (n != runs.voxels) {
        throw std::invalid_argument("mask runs add up to fewer than the mask's voxels");
    }
    return mask;
}

} // namespace steerseg
