#include "solver/leak_watch.hpp"

#include <algorithm>

namespace steerseg::solver {

void LeakWatch::reset() {
    *this = LeakWatch{};
}

std::optional<model::LeakSite> LeakWatch::observe(const GrowthSample& sample) {
    if (!haveTime_ || !(sample.time > lastTime_)) {
        // The first sample, or no evolution since the last (a zero time step): no rate yet.
        haveTime_ = true;
        lastTime_ = sample.time;
        return std::nullopt;
    }
    const auto elapsed = static_cast<double>(sample.time - lastTime_);
    const auto net = static_cast<double>(sample.net);
    const double rate = net / elapsed;
    lastTime_ = sample.time;
    lastRate_ = rate;
    if (said_ || ++samples_ <= kWarmupChecks) {
        return std::nullopt;
    }
    peak_ = std::max(peak_, rate);
    if (peak_ <= 0.0) {
        return std::nullopt;
    }
    if (!slowed_) {
        if (rate <= kSlowedFraction * peak_) {
            slowed_ = true;
            floor_ = std::max(calm_.add(net, elapsed), 0.0);
        }
        return std::nullopt;
    }
    const bool jump = rate >= floor_ + kJumpFraction * peak_ && rate >= kJumpFactor * floor_;
    if (!jump) {
        floor_ = std::min(floor_, std::max(calm_.add(net, elapsed), 0.0));
        jumpRun_ = 0;
        haveBox_ = false;
        return std::nullopt;
    }
    if (sample.anyGained) {
        boxLo_ = haveBox_ ? glm::min(boxLo_, sample.gainLo) : sample.gainLo;
        boxHi_ = haveBox_ ? glm::max(boxHi_, sample.gainHi) : sample.gainHi;
        haveBox_ = true;
    }
    if (++jumpRun_ < kJumpChecks || !haveBox_) {
        return std::nullopt;
    }
    // Once said, the same leak is not said again until the operator acts (reset).
    said_ = true;
    return model::LeakSite{boxLo_, boxHi_, sample.iteration, model::LeakSign::GrowthJump};
}

} // namespace steerseg::solver
