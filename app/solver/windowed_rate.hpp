#pragma once

// A rate over the last N checks: the amount over the span of the newest N intervals (a slow
// front's single quiet check is noise, not its pace). The leak and runaway watches read it.
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

namespace steerseg::solver {

template <int N> class WindowedRate {
  public:
    // Adds one interval (its amount, its span) and returns the rate over the last N of them.
    double add(double amount, double span) {
        window_[static_cast<std::size_t>(count_ % N)] = {amount, span};
        ++count_;
        double amounts = 0.0;
        double spans = 0.0;
        for (int n = 0; n < std::min(count_, N); ++n) {
            amounts += window_[static_cast<std::size_t>(n)].first;
            spans += window_[static_cast<std::size_t>(n)].second;
        }
        return amounts / spans;
    }
    // Intervals added so far.
    [[nodiscard]] int count() const { return count_; }

  private:
    std::array<std::pair<double, double>, static_cast<std::size_t>(N)> window_{};
    int count_ = 0;
};

} // namespace steerseg::solver
