#pragma once

// What a box says about the structure in it (docs/steering.md "The box"): the operator drew it
// around the structure, so the structure is the tissue that fills most of its inner part. Its
// level and spread are the peak of the values' histogram there, not the value at the box's
// centre, which a crescent (a spleen), a ring (an enhancing tumour) or a hollow organ misses.
#include "model/box.hpp"

#include <optional>
#include <vector>

namespace steerseg::workflow {

// The central half of the box along each axis (at least one voxel): where the structure
// outweighs what the box's corners hold besides it.
model::Box innerBox(const model::Box& box);

struct TissuePeak {
    double level = 0.0; // the mean of the values under the histogram's highest peak
    double sigma = 0.0; // the peak's spread, as a normal's standard deviation (from its width)
};

// The histogram's highest peak of `values` (non-finite ones left out) over their 1st..99th
// percentiles, in kBins bins smoothed once: its half-maximum span gives the level (the mean of
// the values in it) and sigma (half its width / 1.1774, a normal's half width at half maximum).
// Fewer than kMinTissueValues finite values: their mean and standard deviation; none: nullopt.
inline constexpr int kTissueBins = 64;
inline constexpr std::size_t kMinTissueValues = 8;
std::optional<TissuePeak> dominantTissue(std::vector<double> values);

} // namespace steerseg::workflow
