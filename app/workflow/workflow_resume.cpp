#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <string>

namespace steerseg::workflow {

namespace {

// Where a resumed session lands: the state it was in, except where that state was a moment
// that cannot be resumed (a run, a write, an error) or needs a level set it does not have.
model::State resumedState(model::State saved, bool hasLevelSet) {
    switch (saved) {
    case model::State::Inspect:
        return model::State::Inspect;
    case model::State::Seeding:
        return model::State::Seeding;
    case model::State::Review:
        return hasLevelSet ? model::State::Review : model::State::Seeding;
    case model::State::Evolving:
    case model::State::Paused:
    case model::State::Exporting:
    case model::State::Done:
    case model::State::Error:
        return hasLevelSet ? model::State::Paused : model::State::Seeding;
    case model::State::NoScan:
    case model::State::Loading:
        break;
    }
    return model::State::Inspect;
}

} // namespace

Workflow::Outcome Workflow::restoreSession(const RestoredSession& restored) {
    if (!scanLoaded_ || status_.state != model::State::Inspect) {
        return no("a session resumes right after its scan loaded, not in " +
                  std::string(model::stateName(status_.state)));
    }
    cause_ = "resume";
    std::string notice = restored.notice;
    try {
        undo_.clear();
        try {
            applyParams(clamped(restored.params), true);
        } catch (const std::exception& e) {
            if (restored.params.speed.kind == model::SpeedKind::Threshold) {
                throw;
            }
            // The level set is back; the speed that shaped it can be chosen again.
            ParamValues threshold = restored.params;
            threshold.speed.kind = model::SpeedKind::Threshold;
            applyParams(clamped(threshold), true);
            notice = "the threshold speed runs: " + oneLine(e.what());
        }
        for (const model::Barrier& b : restored.barriers) {
            if (!engine_.addBarrier(b)) {
                notice = "resumed without some of its corrections' barriers (at most " +
                         std::to_string(model::kMaxBarriers) + ")";
                break;
            }
        }
        status_.seeds = restored.seeds;
        status_.erasures = restored.erasures;
        status_.converged = false;
        refreshEngineStatus();
    } catch (const std::exception& e) {
        enter(model::State::Error, e.what());
        noteAuditError();
        refreshAllowed();
        return no(e.what());
    }
    // Work that was never exported is still unexported.
    dirty_ = status_.hasLevelSet;
    enter(resumedState(restored.state, status_.hasLevelSet), notice);
    noteAuditError();
    refreshAllowed();
    return ok();
}

} // namespace steerseg::workflow
