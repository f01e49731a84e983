#pragma once

namespace steerseg::kiosk {

// Who the machine works for. While the operator acts (an input within the last `quietAfter`
// seconds), frames keep to the frame budget: the solver its configured share
// (IterationBudget), the views previews and tiles sized to what is left of the frame. Once
// nobody has touched anything for that long, the solver runs in slices of `solverSlice`
// seconds with a preview between them (a few a second), and a still picture refines in tiles
// of `refineSlice` seconds: long enough that a frame's fixed costs (panel, composition,
// present, a dispatch) are a small part of it, short enough that the next touch is answered
// within about that time. The first input turns the split back at once.
//
// The screen (views and panel) is composed when something on it changed and otherwise at
// most every `screenInterval` seconds (what the workflow changes on its own: a load's
// progress, an export's end), not for every refinement tile.
class OperatorPacing {
  public:
    struct Settings {
        double quietAfter = 0.5;
        double solverSlice = 0.5;
        double refineSlice = 0.1;
        double screenInterval = 0.25;
    };

    OperatorPacing() = default;
    explicit OperatorPacing(const Settings& settings) : settings_(settings) {}

    // An input (touch, knob, key, a script's step) at `now` (seconds).
    void input(double now) { lastInput_ = now; }
    // The operator started a run (Run, a correction): the press hands the machine to the
    // solver, so the inputs so far hold no frame to the budget. A short run otherwise spent
    // its first `quietAfter` in budget frames, half of it drawing (a 3 s run on llvmpipe lost
    // a tenth, a 0.1 s one on a GPU half); the next input turns the split back as any does.
    void runStarted() { lastInput_ = kNever; }
    [[nodiscard]] bool quiet(double now) const;
    // The solver's time this frame while quiet; 0 while the operator acts (the frame budget's
    // share applies).
    [[nodiscard]] double solverSlice(double now) const;
    // The time a refinement tile may take this frame: `interactive` (what the frame leaves the
    // views) while the operator acts, the refinement slice once quiet or while a script waits
    // for the pictures (`awaited`: its `frame` takes as long as they take, no more).
    [[nodiscard]] double refineSeconds(double now, double interactive, bool awaited) const;
    // Whether the screen must be composed this frame: `changed` (an input, a new picture, a
    // frame to save) or the interval is up. Counts it as composed when true.
    [[nodiscard]] bool screenDue(double now, bool changed);

  private:
    static constexpr double kNever = -1e30; // long enough ago for any quietAfter
    Settings settings_;
    double lastInput_ = kNever;
    double lastScreen_ = kNever;
};

} // namespace steerseg::kiosk
