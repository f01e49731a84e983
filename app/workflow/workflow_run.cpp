// The run: the solver's steps while evolving (with convergence, a vanished surface and an
// engine failure as their own transitions) and the run controls (run, pause, finish, resume).
// The transition table is in workflow.cpp and docs/workflow.md.
#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <exception>
#include <string>

namespace steerseg::workflow {

model::StepResult Workflow::evolve(int iterations) {
    if (status_.state != State::Evolving || iterations <= 0) {
        return {};
    }
    cause_ = "evolve";
    model::StepResult r;
    try {
        r = engine_.step(iterations);
        dirty_ = true;
        status_.converged = r.converged;
        refreshEngineStatus();
    } catch (const std::exception& e) {
        enter(State::Error, oneLine(e.what()));
        noteAuditError();
        return {};
    } catch (...) {
        enter(State::Error, "the solver failed unexpectedly");
        noteAuditError();
        return {};
    }
    if (!status_.hasLevelSet) {
        enter(State::Paused, "the surface vanished: add a seed, or widen eps");
    } else if (r.converged) {
        enter(State::Paused,
              "converged after " + std::to_string(status_.iterations) + " iterations");
    }
    noteAuditError();
    return r;
}

Workflow::Outcome Workflow::on(const Run&) {
    switch (status_.state) {
    case State::Evolving:
        return ok(); // already running: a second press is not a mistake
    case State::Seeding:
    case State::Paused:
        if (!status_.hasLevelSet) {
            return no("no level set to evolve: add a seed first");
        }
        enter(State::Evolving);
        return ok();
    case State::Inspect:
        return no("place a seed before running");
    case State::Review:
        return no("resume steering before running");
    default:
        break;
    }
    if (auto why = whyNoScan()) {
        return no(*why);
    }
    return no("nothing to run in " + std::string(stateName(status_.state)));
}

Workflow::Outcome Workflow::on(const Pause&) {
    if (status_.state == State::Evolving) {
        enter(State::Paused);
        return ok();
    }
    if (status_.state == State::Paused) {
        return ok();
    }
    return no("not running");
}

Workflow::Outcome Workflow::on(const ToggleRun&) {
    if (status_.state == State::Evolving) {
        return on(Pause{});
    }
    return on(Run{});
}

Workflow::Outcome Workflow::on(const Finish&) {
    switch (status_.state) {
    case State::Seeding:
    case State::Evolving:
    case State::Paused:
        if (!status_.hasLevelSet) {
            return no("nothing to review: add a seed first");
        }
        enter(State::Review);
        return ok();
    case State::Review:
        return ok();
    default:
        break;
    }
    if (auto why = whyNoScan()) {
        return no(*why);
    }
    return no("nothing to finish in " + std::string(stateName(status_.state)));
}

Workflow::Outcome Workflow::on(const Resume&) {
    if (status_.state == State::Review) {
        enter(State::Paused);
        return ok();
    }
    return no("resume goes from review back to steering");
}

} // namespace steerseg::workflow
