#include "core/single_outlier.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

namespace steerseg {

double grubbsCritical(std::size_t n, double alpha) {
    if (n < 3 || !(alpha > 0.0 && alpha < 1.0)) {
        throw std::invalid_argument("Grubbs' test needs 3 or more values and alpha in (0, 1)");
    }
    const auto count = static_cast<double>(n);
    const boost::math::students_t_distribution<double> t(count - 2.0);
    const double q = boost::math::quantile(boost::math::complement(t, alpha / (2.0 * count)));
    return (count - 1.0) / std::sqrt(count) * std::sqrt(q * q / (count - 2.0 + q * q));
}

std::optional<std::size_t> singleOutlier(std::span<const double> values, double alpha) {
    const std::size_t n = values.size();
    if (n < 3) {
        return std::nullopt;
    }
    double sum = 0.0;
    for (const double v : values) {
        if (!std::isfinite(v)) {
            return std::nullopt;
        }
        sum += v;
    }
    const double mean = sum / static_cast<double>(n);
    double squares = 0.0;
    std::size_t farthest = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = values[i] - mean;
        squares += d * d;
        if (std::abs(d) > std::abs(values[farthest] - mean)) {
            farthest = i;
        }
    }
    const double sd = std::sqrt(squares / static_cast<double>(n - 1));
    if (!(sd > 0.0)) {
        return std::nullopt;
    }
    if (std::abs(values[farthest] - mean) / sd > grubbsCritical(n, alpha)) {
        return farthest;
    }
    return std::nullopt;
}

} // namespace steerseg
