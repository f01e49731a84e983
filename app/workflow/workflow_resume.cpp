#include "workflow/one_line.hpp"
#include "workflow/workflow.hpp"

#include <memory>
#include <stdexcept>
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

std::string Workflow::structuresProblem(const StructureList& list) const {
    if (list.items.empty() || list.items.size() > model::kMaxStructures ||
        list.active >= list.items.size()) {
        return "no active structure among " + std::to_string(list.items.size());
    }
    const std::size_t voxels = static_cast<std::size_t>(status_.scan.dims.x) *
                               static_cast<std::size_t>(status_.scan.dims.y) *
                               static_cast<std::size_t>(status_.scan.dims.z);
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const Structure& s = list.items[i];
        if (std::string p = model::structureNameProblem(s.info.name); !p.empty()) {
            return p;
        }
        if (list.find(s.info.name) != i) {
            return "two structures are named '" + s.info.name + "'";
        }
        if (!s.mask.runs.empty() && s.mask.voxels != voxels) {
            return "'" + s.info.name + "' has a mask of another size";
        }
    }
    return {};
}

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
        if (restored.structures) {
            if (std::string problem = structuresProblem(*restored.structures); !problem.empty()) {
                throw std::invalid_argument("the autosave's structures: " + problem);
            }
            putStructures(std::make_shared<const StructureList>(*restored.structures));
        }
        refreshEngineStatus();
    } catch (const std::exception& e) {
        enter(model::State::Error, e.what());
        noteAuditError();
        refreshAllowed();
        return no(e.what());
    }
    // Work that was never exported is still unexported.
    dirty_ = hasResult();
    enter(resumedState(restored.state, status_.hasLevelSet), notice);
    noteAuditError();
    refreshAllowed();
    return ok();
}

} // namespace steerseg::workflow
