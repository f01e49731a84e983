#pragma once

namespace steerseg::kiosk {

// How many solver iterations fit in the solver's share of this frame. The cost of an iteration
// grows and shrinks with the front (the active set), so it is learned as it goes: an
// exponential average of the measured seconds per iteration, which follows a growing front
// within a few frames and ignores one slow frame.
class IterationBudget {
  public:
    IterationBudget(double seconds, int minIterations, int maxIterations);

    [[nodiscard]] int next() const;
    void record(int iterations, double seconds);
    [[nodiscard]] double secondsPerIteration() const { return perIteration_; }

  private:
    double seconds_;
    int min_;
    int max_;
    double perIteration_ = 0.0; // 0: nothing measured yet
};

} // namespace steerseg::kiosk
