#include "kiosk/iteration_budget.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::kiosk {

IterationBudget::IterationBudget(double seconds, int minIterations, int maxIterations)
    : seconds_(seconds), min_(minIterations), max_(maxIterations) {
    if (!(seconds > 0.0) || minIterations < 1 || maxIterations < minIterations) {
        throw std::invalid_argument("iteration budget: need seconds > 0 and 1 <= min <= max");
    }
}

int IterationBudget::next() const {
    if (perIteration_ <= 0.0) {
        return min_; // first frame: measure before committing the frame to a guess
    }
    const double fit = std::floor(seconds_ / perIteration_);
    return static_cast<int>(std::clamp(fit, static_cast<double>(min_), static_cast<double>(max_)));
}

void IterationBudget::record(int iterations, double seconds) {
    if (iterations <= 0 || !std::isfinite(seconds) || seconds < 0.0) {
        return;
    }
    const double sample = seconds / iterations;
    constexpr double kWeight = 0.3;
    perIteration_ = perIteration_ <= 0.0 ? sample : (1.0 - kWeight) * perIteration_ + kWeight * sample;
}

} // namespace steerseg::kiosk
