#include "kiosk/iteration_budget.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::kiosk {

IterationBudget::IterationBudget(double share, double frameSeconds, int minIterations,
                                 int maxIterations)
    : share_(share), seconds_(share * frameSeconds), min_(minIterations), max_(maxIterations) {
    if (!(share > 0.0 && share < 1.0) || !(frameSeconds > 0.0) || minIterations < 1 ||
        maxIterations < minIterations) {
        throw std::invalid_argument(
            "iteration budget: need 0 < share < 1, a frame > 0 s and 1 <= min <= max");
    }
}

int IterationBudget::next(double lastFrameSeconds) {
    // A frame that came in under the frame budget earns the share of the budget, not of the
    // shorter frame: on a GPU that draws in a few ms the solver fills the budget's headroom
    // rather than half of a frame nobody waits for (frames stay within the budget).
    const double budget = seconds_ / share_;
    const double frame = std::isfinite(lastFrameSeconds) && lastFrameSeconds > 0.0
                             ? std::max(lastFrameSeconds, budget)
                             : budget;
    // Credit saved over idle frames is capped: a run resumed after a pause must not spend a
    // burst of frames on the solver.
    credit_ = std::min(credit_ + share_ * frame, 2.0 * std::max(seconds_, perIteration_ * min_));
    if (perIteration_ <= 0.0) {
        return min_; // first frame: measure before committing the frame to a guess
    }
    if (credit_ < perIteration_ * min_) {
        return 0;
    }
    const double fit = std::floor(credit_ / perIteration_);
    return static_cast<int>(std::clamp(fit, static_cast<double>(min_), static_cast<double>(max_)));
}

int IterationBudget::forSlice(double seconds) const {
    // A fixed count (min = max) stays fixed: runs that must stop at the same count (tests).
    if (perIteration_ <= 0.0 || !(seconds > 0.0) || min_ == max_) {
        return min_;
    }
    // At most twice the last call's count: the estimate lags a front that starts to grow, and
    // a slice sized by it must not turn into a stall.
    const double most = std::max(2.0 * lastCount_, static_cast<double>(min_));
    return static_cast<int>(
        std::clamp(std::floor(seconds / perIteration_), static_cast<double>(min_), most));
}

void IterationBudget::record(int iterations, double seconds) {
    if (iterations <= 0 || !std::isfinite(seconds) || seconds < 0.0) {
        return;
    }
    lastCount_ = iterations;
    const double sample = seconds / iterations;
    constexpr double kWeight = 0.3;
    perIteration_ =
        perIteration_ <= 0.0 ? sample : (1.0 - kWeight) * perIteration_ + kWeight * sample;
    // One very slow call (the driver compiling, the machine busy) repays a few frames' worth,
    // not a stall.
    credit_ = std::max(credit_ - seconds, -4.0 * std::max(seconds_, perIteration_));
}

} // namespace steerseg::kiosk
