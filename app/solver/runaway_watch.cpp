#include "solver/runaway_watch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace steerseg::solver {

void RunawayWatch::reset() {
    *this = RunawayWatch{factor_};
}

std::optional<model::LeakSite> RunawayWatch::observe(const FrontCheck& check) {
    if (!started_ || check.iteration <= lastIteration_) {
        // The first check sets the clock; one without iterations (a zero step) says nothing.
        started_ = true;
        lastIteration_ = std::max(lastIteration_, check.iteration);
        return std::nullopt;
    }
    const int iterations = check.iteration - lastIteration_;
    lastIteration_ = check.iteration;
    if (said_ || check.front == 0) {
        return std::nullopt;
    }
    const double front = static_cast<double>(check.front);
    const auto net = static_cast<double>(check.net());
    if (!slowed_) {
        if (++checks_ < 2) {
            return std::nullopt; // a new seed's first interval sets no peak
        }
        const double speed = net / (front * iterations);
        peak_ = std::max(peak_, speed);
        if (peak_ > 0.0 && speed <= kSlowedFraction * peak_) {
            slowed_ = true;
            recent_.add(net, iterations); // the reference rate starts here
            const double area = front / 2.0;
            bound_ = std::pow(area, 1.5) / (6.0 * std::sqrt(std::numbers::pi));
        }
        return std::nullopt;
    }
    const double recent = recent_.add(net, iterations);
    if (recent_.count() == kRateChecks) {
        reference_ = recent; // over the slowdown's check and the next
    }
    since_ += check.net();
    if (check.gained > 0) {
        boxLo_ = haveBox_ ? glm::min(boxLo_, check.gainLo) : check.gainLo;
        boxHi_ = haveBox_ ? glm::max(boxHi_, check.gainHi) : check.gainHi;
        haveBox_ = true;
    }
    ratio_ = static_cast<double>(since_) / bound_;
    if (recent_.count() < kRateChecks || ratio_ <= factor_ || recent < reference_ || !haveBox_) {
        return std::nullopt;
    }
    // Said once, as LeakWatch does, until the operator acts (reset).
    said_ = true;
    return model::LeakSite{boxLo_, boxHi_, check.iteration, model::LeakSign::RunawayFill};
}

} // namespace steerseg::solver
