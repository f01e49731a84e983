#pragma once

namespace steerseg::kiosk {

// How many solver iterations to run in this frame so the solver gets its share of the time.
// The cost of an iteration grows and shrinks with the front (the active set), so it is learned
// as it goes: an exponential average of the measured seconds per iteration, which follows a
// growing front within a few frames and ignores one slow frame. Each frame earns the solver its
// share of the time the last frame took, or of the frame budget when the frame took less;
// iterations spend it. When one iteration costs more
// than that (a large scan on a software rasteriser), the solver runs every few frames and the
// frames between stay quick for the operator's input, instead of every frame running late.
class IterationBudget {
  public:
    // share: the part of the time the solver may take (config frame.solver_share);
    // frameSeconds: the frame budget, what a frame is assumed to take before one is measured.
    IterationBudget(double share, double frameSeconds, int minIterations, int maxIterations);

    // This frame's iterations given how long the last frame took; 0 = let this frame go by
    // (the solver has had its share).
    [[nodiscard]] int next(double lastFrameSeconds);
    // The iterations that fit `seconds` (a slice of the machine while nobody touches it,
    // OperatorPacing), at least the minimum; not bounded by the per-frame maximum, which keeps
    // frames short while the operator acts, unless min = max (a fixed count).
    [[nodiscard]] int forSlice(double seconds) const;
    void record(int iterations, double seconds);
    // A run starts: the next slice starts from the minimum and doubles (forSlice), so that
    // its first picture comes within an iteration or two, not after a whole slice sized by
    // the last run's count.
    void restartSlices() { lastCount_ = 0; }
    [[nodiscard]] double secondsPerIteration() const { return perIteration_; }

  private:
    double share_;
    double seconds_; // the frame budget's share: the credit's scale
    int min_;
    int max_;
    double perIteration_ = 0.0; // 0: nothing measured yet
    double credit_ = 0.0;       // seconds of solver time earned and not yet spent
    int lastCount_ = 0;         // the iterations of the last record()
};

} // namespace steerseg::kiosk
