#include "mask_dice.hpp"

#include <itkImageRegionConstIterator.h>
#include <stdexcept>

namespace steerseg::itkbench {

DiceResult maskDice(const MaskImage* a, const MaskImage* b) {
    if (const std::string why = gridMismatch(a, b); !why.empty()) {
        throw std::runtime_error("masks are on different grids: " + why);
    }
    DiceResult r;
    itk::ImageRegionConstIterator<MaskImage> ia(a, a->GetLargestPossibleRegion());
    itk::ImageRegionConstIterator<MaskImage> ib(b, b->GetLargestPossibleRegion());
    for (ia.GoToBegin(), ib.GoToBegin(); !ia.IsAtEnd(); ++ia, ++ib) {
        const bool inA = ia.Get() != 0;
        const bool inB = ib.Get() != 0;
        r.aVoxels += inA ? 1 : 0;
        r.bVoxels += inB ? 1 : 0;
        r.overlap += (inA && inB) ? 1 : 0;
    }
    const long long total = r.aVoxels + r.bVoxels;
    r.dice = total == 0 ? 1.0 : 2.0 * static_cast<double>(r.overlap) / static_cast<double>(total);
    return r;
}

} // namespace steerseg::itkbench
