#pragma once

// The range and fine step of each parameter for one scan, and the clamping every change goes
// through, so a knob, the panel and a script all land on the same values.
#include "workflow/status.hpp"

#include <array>
#include <cstddef>

namespace steerseg::workflow {

using ParamRanges = std::array<ParamRange, model::kParamCount>;

inline constexpr std::size_t indexOf(model::Param param) {
    return static_cast<std::size_t>(param);
}

// T in [min, max], eps in [0, max - min], alpha in [0, 1], the brush radius in
// [1, half the smallest extent] voxels. Fine steps: about a thousandth of the span rounded to a
// 1-2-5 value for T and eps, 0.01 for alpha, half a voxel for the radius. Assumes finite
// values with min <= max (the workflow refuses a scan that has not).
ParamRanges rangesFor(const ScanInfo& scan);

// The 1-2-5 value (..., 0.1, 0.2, 0.5, 1, 2, 5, 10, ...) nearest to a positive finite x in
// ratio; 1 for anything else.
double niceStep(double x);

// v clamped to the range; NaN is the caller's to refuse.
double clampTo(const ParamRange& range, double v);
// The same as a float that still lies inside the range (rounding to float may leave it).
float clampToFloat(const ParamRange& range, double v);

} // namespace steerseg::workflow
