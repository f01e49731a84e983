#pragma once

#include "itk_image_io.hpp"

namespace steerseg::itkbench {

struct DiceResult {
    double dice = 0.0; // 2|A and B| / (|A| + |B|); 1 when both masks are empty
    long long aVoxels = 0;
    long long bVoxels = 0;
    long long overlap = 0;
};

// Dice of two masks on the same grid (non-zero = inside). Throws std::runtime_error naming the
// difference when the grids do not match: a Dice across grids would be meaningless.
DiceResult maskDice(const MaskImage* a, const MaskImage* b);

} // namespace steerseg::itkbench
