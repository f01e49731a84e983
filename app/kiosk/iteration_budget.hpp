#pragma once

namespace steerseg::kiosk {

// How many solver iterations to run in this frame so the solver gets its share of the time.
// The cost of an iteration grows and shrinks with the front (the active set), so it is learned
// as it goes: an exponential average of the measured seconds per iteration, which follows a
// growing front within a few frames and ignores one slow frame. Each frame earns the solver its
// share; iterations spend it. When one iteration costs more than a frame's share (a large scan
// on a software rasteriser), the solver runs every few frames and the frames between stay
// quick for the operator's input, instead of every frame running late.
class IterationBudget {
  public:
    IterationBudget(double seconds, int minIterations, int maxIterations);

    // This frame's iterations; 0 = let this frame go by (the solver has used its share).
    [[nodiscard]] int next();
    void record(int iterations, double seconds);
    [[nodiscard]] double secondsPerIteration() const { return perIteration_; }

  private:
    double seconds_;
    int min_;
    int max_;
    double perIteration_ = 0.0; // 0: nothing measured yet
    double credit_ = 0.0;       // seconds of solver time earned and not yet spent
};

} // namespace steerseg::kiosk
