#pragma once

// A binary mask as alternating run lengths (outside first): a segmentation of a 512^3 scan is
// a few thousand runs per slice, so undo history and autosaves keep masks at a few percent of
// one byte per voxel.
#include <cstdint>
#include <span>
#include <vector>

namespace steerseg {

struct MaskRuns {
    std::size_t voxels = 0;
    std::vector<std::uint32_t> runs; // outside, inside, outside, ... (zero-length runs allowed)
};

MaskRuns encodeRuns(std::span<const std::uint8_t> mask); // non-zero = inside
// Throws std::invalid_argument when the runs do not add up to `voxels`.
std::vector<std::uint8_t> decodeRuns(const MaskRuns& runs);

} // namespace steerseg
