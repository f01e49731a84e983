#pragma once

// An operator's corrections replayed through the kiosk's own workflow and engine, without a
// screen: the clicks protocol's product side (docs/steering.md). `segment --click` and the
// steering benchmark both run it, so a case on the command line is the benchmark's case. Each
// click is one model::Correct, as a tap in add or remove mode is, and a box one model::SetBox,
// as a drawn one is; the solver then runs from
// the current surface to its own stop (converged or a leak) or the click's iteration cap.
#include "engine/session_engine.hpp"
#include "model/action.hpp"
#include "workflow/audit_log.hpp"
#include "workflow/settings.hpp"
#include "workflow/workflow.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace steerseg::engine {

// Why a click's run ended: "converged", "leak", "iteration_limit", or "vanished" (nothing left
// inside: an erase took it all or the run shrank away; `segment` without clicks says the same).
struct ClickOutcome {
    std::string stopReason;
    // A leak's: model::leakSignName of the watch that saw it; empty otherwise.
    std::string leakWatch;
    int iterations = 0;              // the solver's, after this click
    double seconds = 0.0;            // from the click to the stop, GPU work included
    double firstChangeSeconds = 0.0; // from the click to its edit on the GPU (what the next
                                     // frame shows)
    WorkSeconds firstChangeWork;     // the engine's part of it (the rest: the workflow's own)
    double T = 0.0;
    double eps = 0.0;
    int barriers = 0;
    bool takenBack = false;    // an erase's run grew too far and went back to the erase
    bool withdrawOnly = false; // an erase's run withdrew beyond its reach from the start
};

class ClickSession {
  public:
    // Loads the scan as the kiosk does (LoadScan, polled until it is attached) with a current
    // GLES 3.1 context. std::runtime_error with the reader's message when it cannot.
    ClickSession(const std::string& scanPath, const workflow::Settings& settings,
                 EdgeSpeedRules edge = {}, model::SolverOptions options = consoleSolverOptions());
    ClickSession(const ClickSession&) = delete;
    ClickSession& operator=(const ClickSession&) = delete;

    // One prompt and the run that follows, at most maxIterations: a click (model::Correct) or
    // a box (model::SetBox: on a scan without a level set its probe and seed, then the run).
    // std::runtime_error with the workflow's reason when it refuses the prompt (a negative
    // first click, outside the scan, an inverted box).
    ClickOutcome apply(const model::Action& prompt, int maxIterations);

    // 1 inside, i fastest, on the scan's grid.
    [[nodiscard]] std::vector<std::uint8_t> mask();
    [[nodiscard]] const Volume& scan();
    [[nodiscard]] const workflow::Workflow& workflow() const { return flow_; }
    [[nodiscard]] SessionEngine& engine() { return engine_; }

  private:
    SessionEngine engine_;
    workflow::Workflow flow_;
};

} // namespace steerseg::engine
