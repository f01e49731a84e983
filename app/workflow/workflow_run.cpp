// The run: the solver's steps while evolving (with convergence, a vanished surface and an
// engine failure as their own transitions) and the run controls (run, pause, finish, resume).
// Which control is allowed when, and the state it leads to, is the transition table's
// (transition_table.hpp): the controls themselves have no effect beyond their transition.
#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <exception>
#include <string>

namespace steerseg::workflow {

model::StepResult Workflow::evolve(int iterations) {
    if (status_.state != model::State::Evolving || iterations <= 0) {
        return {};
    }
    cause_ = "evolve";
    model::StepResult r;
    bool vanished = false;
    try {
        r = engine_.step(iterations);
        dirty_ = true;
        status_.converged = r.converged;
        refreshEngineStatus();
        if (takeBackEraseRun()) {
            // The run goes on from the erase: what this step said of its end is the grown one's.
            r.converged = false;
            r.stopReason = model::StopReason::IterationLimit;
            r.leak.reset();
            status_.converged = false;
        }
        // A run that shrank away converges on nothing: the exact count at its stop tells.
        vanished = !status_.hasLevelSet || (r.converged && engine_.exactVolumeMl() <= 0.0);
        status_.hasLevelSet = !vanished;
    } catch (const std::exception& e) {
        enter(model::State::Error, oneLine(e.what()));
        noteAuditError();
        refreshAllowed();
        return {};
    } catch (...) {
        enter(model::State::Error, "the solver failed unexpectedly");
        noteAuditError();
        refreshAllowed();
        return {};
    }
    if (vanished) {
        status_.converged = false; // on nothing
        enter(model::State::Paused, "the surface vanished: add a seed, or widen eps");
    } else if (r.stopReason == model::StopReason::Leak && r.leak) {
        const glm::ivec3 c(r.leak->centre());
        // Which watch saw it, so that an operator (and the audit log) can tell a jump through a
        // gap from a fill that never slowed (issue 51: the second calls some slow creeps).
        const char* how = r.leak->sign == model::LeakSign::RunawayFill
                              ? "filling on after it had slowed"
                              : "its growth jumping after a slowdown";
        enter(model::State::Paused, "the front broke out near (" + std::to_string(c.x) + ", " +
                                        std::to_string(c.y) + ", " + std::to_string(c.z) + "), " +
                                        how + ": erase there, or narrow eps, then run");
    } else if (r.converged) {
        enter(model::State::Paused,
              "converged after " + std::to_string(status_.iterations) + " iterations");
    }
    noteAuditError();
    refreshAllowed();
    return r;
}

Workflow::Outcome Workflow::on(const model::Run&) {
    return ok();
}

Workflow::Outcome Workflow::on(const model::Pause&) {
    return ok();
}

Workflow::Outcome Workflow::on(const model::ToggleRun&) {
    return ok();
}

Workflow::Outcome Workflow::on(const model::Finish&) {
    return ok();
}

Workflow::Outcome Workflow::on(const model::Resume&) {
    return ok();
}

} // namespace steerseg::workflow
