#include "workflow/param_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace steerseg::workflow {

double niceStep(double x) {
    if (!std::isfinite(x) || x <= 0.0) {
        return 1.0;
    }
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    const double m = x / decade; // in [1, 10)
    // Boundaries at the geometric means of neighbours: nearest in ratio.
    double mantissa = 10.0;
    if (m < std::sqrt(2.0)) {
        mantissa = 1.0;
    } else if (m < std::sqrt(10.0)) {
        mantissa = 2.0;
    } else if (m < std::sqrt(50.0)) {
        mantissa = 5.0;
    }
    return mantissa * decade;
}

ParamRanges rangesFor(const ScanInfo& scan) {
    const double span = scan.maxValue - scan.minValue;
    const double valueStep = niceStep(span / 1000.0);
    // The smallest extent that is not flat: a one-slice image still gets an in-plane brush.
    int smallest = 0;
    for (int a = 0; a < 3; ++a) {
        if (scan.dims[a] > 1 && (smallest == 0 || scan.dims[a] < smallest)) {
            smallest = scan.dims[a];
        }
    }
    ParamRanges r{};
    r[indexOf(model::Param::T)] = {scan.minValue, scan.maxValue, valueStep};
    r[indexOf(model::Param::Eps)] = {0.0, span, valueStep};
    r[indexOf(model::Param::Alpha)] = {0.0, 1.0, 0.01};
    r[indexOf(model::Param::Radius)] = {1.0, std::max(1.0, smallest / 2.0), 0.5};
    return r;
}

double clampTo(const ParamRange& range, double v) {
    return std::clamp(v, range.min, range.max);
}

float clampToFloat(const ParamRange& range, double v) {
    float f = static_cast<float>(clampTo(range, v));
    if (static_cast<double>(f) > range.max) {
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
    if (static_cast<double>(f) < range.min) {
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    }
    return f;
}

} // namespace steerseg::workflow
