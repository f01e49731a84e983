#include "solver/settle_watch.hpp"

#include <algorithm>
#include <cstdlib>

namespace steerseg::solver {

void SettleWatch::reset() {
    *this = SettleWatch{window_, tolerance_};
}

bool SettleWatch::observe(const FrontCheck& check) {
    if (!started_) {
        // The first check after a start or an edit only sets the clock: its interval began
        // before the watch knew (an edit's own changes are not the front's motion).
        started_ = true;
        start_ = check.iteration;
        return false;
    }
    if (check.iteration <= (checks_.empty() ? start_ : checks_.back().end)) {
        return false; // no iteration since the last check (a zero time step)
    }
    checks_.push_back({check.iteration, check.net()});
    windowNet_ += check.net();
    // The shortest trailing run of checks that still spans the window.
    while (checks_.size() > 1 && check.iteration - checks_.front().end >= window_) {
        start_ = checks_.front().end;
        windowNet_ -= checks_.front().net;
        checks_.pop_front();
    }
    if (check.iteration - start_ < window_) {
        lastDisplacement_ = 0.0;
        return false;
    }
    lastDisplacement_ = static_cast<double>(std::llabs(windowNet_)) /
                        static_cast<double>(std::max<std::uint32_t>(check.front, 1));
    return lastDisplacement_ < tolerance_;
}

} // namespace steerseg::solver
