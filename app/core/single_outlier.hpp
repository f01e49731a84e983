#pragma once

// Grubbs' test for one outlier in a sample taken as normal (two-sided): the value farthest from
// the mean is an outlier when its distance, in sample standard deviations, exceeds
// G = (n - 1) / sqrt(n) * sqrt(t^2 / (n - 2 + t^2)), t the upper alpha / (2n) quantile of
// Student's t with n - 2 degrees of freedom (Grubbs 1969; NIST/SEMATECH e-Handbook 1.3.5.17).
// It finds one stray value, not a tail: a tail of many values widens the standard deviation it
// is measured in. GL-free.
#include <cstddef>
#include <optional>
#include <span>

namespace steerseg {

// The index of the outlier, if the test finds one at `alpha` (in (0, 1)); none for fewer than 3
// values, for values all equal, or where a value is not finite.
std::optional<std::size_t> singleOutlier(std::span<const double> values, double alpha = 0.05);

// The critical G for n >= 3 values at `alpha`.
double grubbsCritical(std::size_t n, double alpha);

} // namespace steerseg
