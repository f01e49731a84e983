#include "seed_level_set.hpp"

#include "cli/args.hpp"

#include <algorithm>
#include <cmath>
#include <itkImageRegionIteratorWithIndex.h>
#include <limits>
#include <stdexcept>

namespace steerseg::itkbench {

Seed parseSeed(const std::string& text) {
    const std::vector<double> v = cli::parseNumberList(text, 4, "--seed");
    if (!(v[3] > 0.0)) {
        throw cli::UsageError("--seed: radius must be > 0, got '" + text + "'");
    }
    return Seed{v[0], v[1], v[2], v[3]};
}

FloatImage::Pointer seedLevelSet(const itk::ImageBase<3>* grid, std::span<const Seed> seeds) {
    if (seeds.empty()) {
        throw std::runtime_error("at least one seed is needed");
    }
    const auto size = grid->GetLargestPossibleRegion().GetSize();
    for (const Seed& s : seeds) {
        const double c[3] = {s.i, s.j, s.k};
        for (unsigned d = 0; d < 3; ++d) {
            if (c[d] < 0.0 || c[d] > static_cast<double>(size[d]) - 1.0) {
                throw std::runtime_error("seed centre outside the grid " + std::to_string(size[0]) +
                                         "x" + std::to_string(size[1]) + "x" +
                                         std::to_string(size[2]));
            }
        }
    }
    auto phi = FloatImage::New();
    phi->CopyInformation(grid);
    phi->SetRegions(grid->GetLargestPossibleRegion());
    phi->Allocate();
    itk::ImageRegionIteratorWithIndex<FloatImage> it(phi, phi->GetLargestPossibleRegion());
    for (it.GoToBegin(); !it.IsAtEnd(); ++it) {
        const auto idx = it.GetIndex();
        double d = std::numeric_limits<double>::max();
        for (const Seed& s : seeds) {
            const double di = static_cast<double>(idx[0]) - s.i;
            const double dj = static_cast<double>(idx[1]) - s.j;
            const double dk = static_cast<double>(idx[2]) - s.k;
            d = std::min(d, std::sqrt(di * di + dj * dj + dk * dk) - s.r);
        }
        it.Set(static_cast<float>(d));
    }
    return phi;
}

} // namespace steerseg::itkbench
