#include "workflow/workflow.hpp"

#include "workflow/one_line.hpp"

#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>

// Which action is allowed in which state, under which guard and to which state, is the table in
// transition_table.hpp (docs/workflow.md prints it); handle() runs it before an action's effect.

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
bool keepsNotice(const model::Action& action) {
    return std::holds_alternative<model::RotateView>(action) ||
           std::holds_alternative<model::ZoomView>(action) ||
           std::holds_alternative<model::PageSlice>(action) ||
           std::holds_alternative<model::SetSlice>(action) ||
           std::holds_alternative<model::ShowSlices>(action) ||
           std::holds_alternative<model::SelectParam>(action) ||
           std::holds_alternative<model::CycleParam>(action) ||
           std::holds_alternative<model::SetEraseMode>(action) ||
           std::holds_alternative<model::SetOutsideMode>(action) ||
           std::holds_alternative<model::SetBoxMode>(action) ||
           std::holds_alternative<model::SetWindow>(action) ||
           std::holds_alternative<model::SearchPacs>(action) ||
           std::holds_alternative<model::RetrievePacs>(action) ||
           std::holds_alternative<model::CancelRetrieve>(action) ||
           std::holds_alternative<model::ListPacsSeries>(action) ||
           std::holds_alternative<model::Quit>(action);
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
    for (const model::StructureInfo& k : settings_.structureKinds) {
        status_.structureKinds.push_back(k.name);
    }
    for (const SpeedOff& off : settings_.speedsOff) {
        status_.speedsOff.push_back(off.kind);
        status_.gpuAlarm += std::string(status_.gpuAlarm.empty() ? "" : " ") + "The " +
                            std::string(model::speedKindName(off.kind)) +
                            " speed is off: this GPU computed it wrong at start-up (" + off.why +
                            ").";
    }
    const std::string fallback(model::speedKindName(settings_.defaultSpeed));
    if (!settings_.defaultSpeedFailed.empty()) {
        status_.gpuAlarm += std::string(status_.gpuAlarm.empty() ? "" : " ") + "The " + fallback +
                            " speed failed too (" + settings_.defaultSpeedFailed +
                            "): no mask of this GPU can be trusted.";
    } else if (!status_.gpuAlarm.empty()) {
        status_.gpuAlarm += " The " + fallback + " speed runs instead.";
    }
    if (!status_.gpuAlarm.empty()) {
        status_.gpuAlarm = "GPU CHECK FAILED. " + status_.gpuAlarm;
    }
    status_.radius = settings_.defaultRadius;
    params_.values[indexOf(model::Param::Radius)] = settings_.defaultRadius;
    noteAuditError();
    refreshAllowed();
}

Workflow::~Workflow() = default;

Workflow::Outcome Workflow::handle(const model::Action& action) {
    const model::State before = status_.state;
    structureBefore_ = structures_.active < structures_.items.size()
                           ? structures_.items[structures_.active].info.name
                           : std::string();
    pending_.clear();
    handling_ = true;
    cause_ = model::actionName(action);
    std::string notice = status_.message;
    if (!keepsNotice(action) && before != model::State::Error) {
        status_.message.clear();
    }
    Outcome out;
    try {
        const Verdict verdict = decide(before, model::kindOf(action), facts());
        if (!verdict.allowed) {
            out = no(verdict.refusal);
        } else {
            out = std::visit([this](const auto& a) { return on(a); }, action);
            // The effect may have moved the state itself (an export ends in done, or back in
            // review); the table's next state is for the actions that do not.
            // Nothing evolves without a surface (an erase may have left none).
            const bool runsEmpty = verdict.next == model::State::Evolving && !status_.hasLevelSet;
            if (out.accepted && verdict.next && status_.state == before && !runsEmpty) {
                enter(*verdict.next);
            }
        }
    } catch (const std::exception& e) {
        out = no(oneLine(e.what()));
    } catch (...) {
        out = no("unexpected failure");
    }
    handling_ = false;
    if (!out.accepted) {
        // In Error the error stays on screen; elsewhere the refusal is the newest notice.
        status_.message = status_.state == model::State::Error ? std::move(notice) : out.reason;
    }
    refreshAllowed();
    record(action, before, out);
    refreshAllowed(); // the record may have found the audit log lost, or written again
    return out;
}

void Workflow::update() {
    if (audit_ != nullptr && !audit_->ok()) {
        audit_->retry();
        noteAuditError();
        refreshAllowed();
    }
    if (status_.state != model::State::Loading) {
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
        enter(model::State::NoScan, poll.error.empty() ? std::string("the scan could not be read")
                                                       : oneLine(poll.error.c_str()));
        break;
    }
    noteAuditError();
    refreshAllowed();
}

void Workflow::enter(model::State next, std::string message) {
    const model::State from = status_.state;
    status_.state = next;
    if (next == model::State::Review && from != model::State::Review) {
        measureStructures();
    } else if (next != model::State::Review && next != model::State::Exporting &&
               next != model::State::Done) {
        status_.measurements.clear(); // the surfaces may change from here
    }
    if (from == model::State::Evolving && next != model::State::Evolving) {
        endReach(); // the next run, whoever starts it, is the whole surface's
        // The readouts during the run may lag a little; the stopped surface's are exact.
        try {
            if (scanLoaded_) {
                status_.volumeMl = engine_.exactVolumeMl();
            }
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
    return scanLoaded_ && dirty_ && hasResult();
}

bool Workflow::hasResult() const {
    if (status_.hasLevelSet) {
        return true;
    }
    for (std::size_t i = 0; i < structures_.items.size(); ++i) {
        if (i != structures_.active && !structures_.items[i].mask.runs.empty()) {
            return true;
        }
    }
    return false;
}

Facts Workflow::facts() const {
    return {status_.hasLevelSet,
            unexportedWork(),
            undo_.undoTop() != nullptr,
            undo_.redoTop() != nullptr,
            params_.speed.hasInside() || params_.speed.hasOutside(),
            !status_.auditProblem.empty(),
            status_.auditAcknowledged,
            params_.speed.box.has_value(),
            hasResult()};
}

void Workflow::refreshAllowed() {
    refreshUndoFlags();
    status_.unexported = unexportedWork();
    status_.allowed = allowedActions(status_.state, facts());
}

// The audit's problem is the status's own line, not the message: the next notice must not
// replace it. Its acknowledgement lasts while the log stays lost.
void Workflow::noteAuditError() {
    if (audit_ != nullptr) {
        status_.auditProblem = audit_->problem();
        if (status_.auditProblem.empty()) {
            status_.auditAcknowledged = false;
        }
    }
}

void Workflow::record(const model::Action& action, model::State before, const Outcome& outcome) {
    if (audit_ == nullptr) {
        return;
    }
    try {
        const nlohmann::json result = outcome.accepted ? resultOf(action) : nlohmann::json();
        audit_->action(before, action, result, status_.scan.identity, outcome.accepted,
                       outcome.reason, structureBefore_);
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
    status_.eraseRunsTakenBack = 0;
    status_.erasesWithdrawOnly = 0;
    erasesCreep_ = false;
    status_.preset.clear();
    status_.exportedPath.clear();
    status_.exportedFiles.clear();
    status_.eraseMode = false;
    status_.outsideMode = false;
    status_.boxMode = false;
    status_.boxFace.reset();
    status_.insideExamples.clear(); // the next scan's examples start with its first probe
    status_.outsideExamples.clear();
    status_.paintedInside.clear();
    status_.paintedOutside.clear();
    status_.box.reset();
    status_.view = ViewState{};
    structures_ = {};
    status_.structures.clear();
}

Workflow::Outcome Workflow::on(const model::LoadScan& a) {
    if (a.path.empty()) {
        return no("no scan path given");
    }
    // The old scan's snapshots go while the engine still holds it.
    undo_.clear();
    engine_.beginLoad(a.path);
    forgetScan();
    status_.message.clear(); // an error left over from the last scan is not this one's
    return ok();
}

void Workflow::finishLoad() {
    ScanInfo info;
    try {
        info = engine_.scanInfo();
    } catch (const std::exception& e) {
        enter(model::State::NoScan, oneLine(e.what()));
        return;
    }
    const bool sized = info.dims.x >= 1 && info.dims.y >= 1 && info.dims.z >= 1;
    const bool valued = std::isfinite(info.minValue) && std::isfinite(info.maxValue) &&
                        info.minValue <= info.maxValue;
    if (!sized || !valued) {
        enter(model::State::NoScan,
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
    status_.selected = model::Param::T;
    status_.loadProgress = 1.0;
    scanLoaded_ = true;
    try {
        setDefaultParams();
        firstStructure();
        refreshEngineStatus();
    } catch (const std::exception& e) {
        forgetScan();
        enter(model::State::NoScan, oneLine(e.what()));
        return;
    }
    enter(model::State::Inspect);
}

// Proceed and Back are the table's steps; from review the step forward is the export.
Workflow::Outcome Workflow::on(const model::Proceed&) {
    return status_.state == model::State::Review ? exportTo({}) : ok();
}

Workflow::Outcome Workflow::on(const model::Back&) {
    return ok();
}

Workflow::Outcome Workflow::on(const model::Dismiss&) {
    status_.message.clear();
    if (status_.state == model::State::Error) {
        if (!scanLoaded_) {
            enter(model::State::NoScan);
        } else if (status_.hasLevelSet) {
            enter(model::State::Paused);
        } else {
            enter(model::State::Inspect);
        }
    }
    return ok();
}

Workflow::Outcome Workflow::on(const model::AcknowledgeAudit&) {
    status_.auditAcknowledged = true;
    return ok();
}

Workflow::Outcome Workflow::on(const model::Quit&) {
    quit_ = true;
    return ok();
}

} // namespace steerseg::workflow
