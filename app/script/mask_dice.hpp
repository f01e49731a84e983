#pragma once

// The overlap of an exported mask with a reference label file, for scripted end-to-end checks.
#include <filesystem>

namespace steerseg::script {

// Dice = 2|A and B| / (|A| + |B|) of the mask's non-zero voxels (A) and the reference's voxels
// equal to `label`, or non-zero ones when label < 0 (B), both read with the scan readers. Throws
// std::runtime_error with one line when a file does not read or the grids differ in size;
// two empty sets give 1.
double maskDice(const std::filesystem::path& mask, const std::filesystem::path& reference,
                int label);

} // namespace steerseg::script
