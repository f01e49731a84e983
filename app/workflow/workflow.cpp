#include "workflow/workflow.hpp"

#include "workflow/one_line.hpp"

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>

// The transition table (docs/workflow.md says the same for operators and script writers).
//
//   state      action                  next        condition / note
//   ---------  ----------------------  ----------  -----------------------------------------
//   any        LoadScan                Loading     refused while unexported work exists (a
//                                                  level set changed since its last export:
//                                                  "export or restart first") and in Exporting
//   Loading    update(): Ready         Inspect     ranges from the scan, default parameters,
//                                                  view reset
//   Loading    update(): Failed        NoScan      the reader's message in status.message
//   Inspect    AddSeed                 Seeding     the seed is placed
//   Inspect    Proceed                 Seeding
//   Seeding    Back                    Inspect
//   Seeding    Run, ToggleRun, Proceed Evolving    needs a level set
//   Paused     Run, ToggleRun          Evolving    needs a level set
//   Evolving   Pause, ToggleRun        Paused
//   Evolving   evolve(): converged     Paused      notice "converged after N iterations"
//   Evolving   evolve(): surface gone  Paused      notice
//   Evolving   evolve(): engine throws Error       the engine's message
//   Evolving   Erase empties the set   Paused      notice
//   Evolving   Undo, Redo              Paused      then the undo or redo
//   Seeding,   Finish, Proceed*        Review      needs a level set (*not from Seeding)
//    Evolving, Paused
//   Inspect..  Restart                 Seeding     clears the level set (undoable); from any
//    Done                                          state with a scan and a level set
//   Review     Resume, Back            Paused
//   Review,    Export, Proceed*        Exporting   (*Review only) then Done, or Review with
//    Paused                            -> Done     the writer's message (work kept)
//   Done       Back                    Review
//   Error      Dismiss                 Paused      with a level set; Inspect with a scan;
//                                                  NoScan without
//   any        Quit                    (same)      quitRequested() becomes true
//
// Parameters (Probe, ApplyPreset, SetParam, NudgeParam, NudgeSelected) and the speed (SetSpeed,
// MarkOutside, ClearExamples) change in Inspect, Seeding, Evolving and Paused, live. Spheres:
// AddSeed in Inspect, Seeding, Evolving, Paused; Erase in Seeding, Evolving, Paused. Undo/Redo
// in Inspect, Seeding, Evolving, Paused. The view (RotateView, ZoomView, PageSlice, SetSlice,
// ShowSlices, SetWindow), SelectParam, CycleParam, SetEraseMode and SetOutsideMode in any
// state with a scan. Dismiss in any state clears the notice. Everything
// else is refused with a one-line reason and changes nothing.

namespace steerseg::workflow {

namespace {

Settings validated(Settings s) {
    validateSettings(s);
    if (!s.clock) {
        s.clock = [] { return std::chrono::system_clock::now(); };
    }
    return s;
}

// Actions that leave the operator's notice on screen: looking around must not wipe an error.
bool keepsNotice(const Action& action) {
    return std::holds_alternative<RotateView>(action) || std::holds_alternative<ZoomView>(action) ||
           std::holds_alternative<PageSlice>(action) || std::holds_alternative<SetSlice>(action) ||
           std::holds_alternative<ShowSlices>(action) ||
           std::holds_alternative<SelectParam>(action) ||
           std::holds_alternative<CycleParam>(action) ||
           std::holds_alternative<SetEraseMode>(action) ||
           std::holds_alternative<SetOutsideMode>(action) ||
           std::holds_alternative<SetWindow>(action) || std::holds_alternative<Quit>(action);
}

// In Error the operator acknowledges first; only looking around, loading and quitting go on.
bool allowedInError(const Action& action) {
    return keepsNotice(action) || std::holds_alternative<Dismiss>(action) ||
           std::holds_alternative<LoadScan>(action);
}

} // namespace

Workflow::Workflow(Engine& engine, Settings settings, AuditLog* audit)
    : engine_(engine), settings_(validated(std::move(settings))), audit_(audit),
      undo_(settings_.maxUndo, [this](SnapshotId id) {
          try {
              engine_.drop(id);
          } catch (...) {
              // A snapshot the engine cannot free is its loss, not the operator's.
          }
      }) {
    for (const TissuePreset& p : settings_.presets) {
        status_.presets.push_back(p.name);
    }
    status_.exportFormats = settings_.exportFormats;
    status_.radius = settings_.defaultRadius;
    params_.values[indexOf(Param::Radius)] = settings_.defaultRadius;
    noteAuditError();
}

Workflow::~Workflow() = default;

Workflow::Outcome Workflow::handle(const Action& action) {
    const State before = status_.state;
    pending_.clear();
    handling_ = true;
    cause_ = actionName(action);
    std::string notice = status_.message;
    if (!keepsNotice(action) && before != State::Error) {
        status_.message.clear();
    }
    Outcome out;
    try {
        out = before == State::Error && !allowedInError(action)
                  ? no("dismiss the error first")
                  : std::visit([this](const auto& a) { return on(a); }, action);
    } catch (const std::exception& e) {
        out = no(oneLine(e.what()));
    } catch (...) {
        out = no("unexpected failure");
    }
    handling_ = false;
    if (!out.accepted) {
        // In Error the error stays on screen; elsewhere the refusal is the newest notice.
        status_.message = status_.state == State::Error ? std::move(notice) : out.reason;
    }
    refreshUndoFlags();
    record(action, before, out);
    return out;
}

void Workflow::update() {
    if (status_.state != State::Loading) {
        return;
    }
    cause_ = "load";
    LoadPoll poll;
    try {
        poll = engine_.pollLoad();
    } catch (const std::exception& e) {
        poll.kind = LoadPoll::Failed;
        poll.error = e.what();
    } catch (...) {
        poll.kind = LoadPoll::Failed;
    }
    switch (poll.kind) {
    case LoadPoll::Running:
        status_.loadProgress = std::isfinite(poll.progress) ? poll.progress : -1.0;
        break;
    case LoadPoll::Ready:
        finishLoad();
        break;
    case LoadPoll::Failed:
        enter(State::NoScan, poll.error.empty() ? std::string("the scan could not be read")
                                                : oneLine(poll.error.c_str()));
        break;
    }
    noteAuditError();
}

void Workflow::enter(State next, std::string message) {
    const State from = status_.state;
    status_.state = next;
    if (from == State::Evolving && next != State::Evolving && scanLoaded_) {
        // The readouts during the run may lag a little; the stopped surface's are exact.
        try {
            status_.volumeMl = engine_.exactVolumeMl();
        } catch (const std::exception&) {
            // The engine's failure surfaces on the next call that needs it; the readout stays.
        }
    }
    if (!message.empty()) {
        status_.message = message;
    }
    if (audit_ == nullptr) {
        return;
    }
    if (handling_) {
        pending_.push_back({from, next, std::move(message)});
    } else {
        audit_->transition(from, next, cause_, status_.scan.identity, message);
    }
}

bool Workflow::unexportedWork() const {
    return scanLoaded_ && dirty_ && status_.hasLevelSet;
}

std::optional<std::string> Workflow::whyNoScan() const {
    if (scanLoaded_) {
        return std::nullopt;
    }
    if (status_.state == State::Loading) {
        return "a scan is loading";
    }
    return "no scan loaded: load one first";
}

void Workflow::noteAuditError() {
    if (audit_ != nullptr) {
        if (auto e = audit_->takeError()) {
            status_.message = *e;
        }
    }
}

void Workflow::record(const Action& action, State before, const Outcome& outcome) {
    if (audit_ == nullptr) {
        return;
    }
    try {
        const nlohmann::json result = outcome.accepted ? resultOf(action) : nlohmann::json();
        audit_->action(before, action, result, status_.scan.identity, outcome.accepted,
                       outcome.reason);
    } catch (...) {
        // resultOf only reads the status; the log reports its own failures.
    }
    for (const PendingTransition& t : pending_) {
        audit_->transition(t.from, t.to, cause_, status_.scan.identity, t.message);
    }
    pending_.clear();
    noteAuditError();
}

// --- loading -------------------------------------------------------------------------------

void Workflow::forgetScan() {
    scanLoaded_ = false;
    dirty_ = false;
    status_.scan = ScanInfo{};
    status_.ranges = {};
    status_.loadProgress = 0.0;
    status_.hasLevelSet = false;
    status_.seeds = 0;
    status_.erasures = 0;
    status_.iterations = 0;
    status_.evolvedTime = 0.0;
    status_.volumeMl = 0.0;
    status_.converged = false;
    status_.preset.clear();
    status_.exportedPath.clear();
    status_.eraseMode = false;
    status_.outsideMode = false;
    status_.insideExamples.clear(); // the next scan's examples start with its first probe
    status_.outsideExamples.clear();
    status_.view = ViewState{};
}

Workflow::Outcome Workflow::on(const LoadScan& a) {
    if (a.path.empty()) {
        return no("no scan path given");
    }
    if (unexportedWork()) {
        return no("the segmentation is not exported: export or restart first");
    }
    // The old scan's snapshots go while the engine still holds it.
    undo_.clear();
    engine_.beginLoad(a.path);
    forgetScan();
    status_.message.clear(); // an error left over from the last scan is not this one's
    enter(State::Loading);
    return ok();
}

void Workflow::finishLoad() {
    ScanInfo info;
    try {
        info = engine_.scanInfo();
    } catch (const std::exception& e) {
        enter(State::NoScan, oneLine(e.what()));
        return;
    }
    const bool sized = info.dims.x >= 1 && info.dims.y >= 1 && info.dims.z >= 1;
    const bool valued = std::isfinite(info.minValue) && std::isfinite(info.maxValue) &&
                        info.minValue <= info.maxValue;
    if (!sized || !valued) {
        enter(State::NoScan,
              "scan " + info.name +
                  (sized ? ": its value range is not finite" : ": it has no voxels"));
        return;
    }
    if (info.sliceCount.x <= 0 || info.sliceCount.y <= 0 || info.sliceCount.z <= 0) {
        info.sliceCount = glm::ivec3(info.dims.z, info.dims.y, info.dims.x);
    }
    status_.scan = info;
    status_.ranges = rangesFor(info);
    status_.view = ViewState{};
    status_.selected = Param::Target;
    status_.loadProgress = 1.0;
    scanLoaded_ = true;
    try {
        setDefaultParams();
        refreshEngineStatus();
    } catch (const std::exception& e) {
        forgetScan();
        enter(State::NoScan, oneLine(e.what()));
        return;
    }
    enter(State::Inspect);
}

Workflow::Outcome Workflow::on(const Proceed&) {
    switch (status_.state) {
    case State::Inspect:
        enter(State::Seeding);
        return ok();
    case State::Seeding:
        return on(Run{});
    case State::Evolving:
    case State::Paused:
        return on(Finish{});
    case State::Review:
        return on(Export{});
    case State::Done:
        return no("done: load the next scan");
    case State::Error:
        return no("dismiss the error first");
    default:
        break;
    }
    return no(whyNoScan().value_or("nothing to proceed to"));
}

Workflow::Outcome Workflow::on(const Back&) {
    switch (status_.state) {
    case State::Seeding:
        enter(State::Inspect);
        return ok();
    case State::Review:
        enter(State::Paused);
        return ok();
    case State::Done:
        enter(State::Review);
        return ok();
    default:
        break;
    }
    return no("no step back from " + std::string(stateName(status_.state)));
}

Workflow::Outcome Workflow::on(const Dismiss&) {
    status_.message.clear();
    if (status_.state == State::Error) {
        if (!scanLoaded_) {
            enter(State::NoScan);
        } else if (status_.hasLevelSet) {
            enter(State::Paused);
        } else {
            enter(State::Inspect);
        }
    }
    return ok();
}

Workflow::Outcome Workflow::on(const Quit&) {
    quit_ = true;
    return ok();
}

} // namespace steerseg::workflow
