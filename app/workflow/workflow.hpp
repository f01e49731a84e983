#pragma once

// The fixed operator workflow: the only place that decides what an action means in the state
// the console is in. It drives an Engine (the scan, the solver, the writers), keeps the undo
// history and the view state, writes the audit log and publishes a Status for the screen. It
// knows actions, not devices, and runs without a GPU. Which action may happen in which state,
// and which state follows, is the transition table's (transition_table.hpp), which this runs.
#include "model/action.hpp"
#include "workflow/audit_log.hpp"
#include "workflow/engine.hpp"
#include "workflow/param_ranges.hpp"
#include "workflow/settings.hpp"
#include "workflow/status.hpp"
#include "workflow/structures.hpp"
#include "workflow/transition_table.hpp"
#include "workflow/undo_stack.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace steerseg::workflow {

struct TissuePeak; // workflow/box_tissue.hpp

// What a resumed session brings back besides the level set (which the caller has already put
// into the engine): the parameters, the sphere counts the panel shows and the state it was in.
struct RestoredSession {
    ParamValues params;
    int seeds = 0;
    int erasures = 0;
    model::State state = model::State::Paused;
    std::string notice; // for the operator, e.g. "resumed the session saved at 13:01:40 UTC"
    std::vector<model::Barrier> barriers; // placed again on the restored surface
    // The session's structures (the active one's mask empty: the level set is its surface);
    // nullopt: one, as a session before structures had.
    std::optional<StructureList> structures;
};

class Workflow {
  public:
    // Throws std::invalid_argument for invalid settings (validateSettings). The engine and the
    // audit log must outlive the workflow.
    Workflow(Engine& engine, Settings settings, AuditLog* audit = nullptr);
    ~Workflow();
    Workflow(const Workflow&) = delete;
    Workflow& operator=(const Workflow&) = delete;

    struct Outcome {
        bool accepted = false;
        std::string reason; // why it was refused, one line ("" when accepted)
    };
    // The only entry for operator intent. Never throws: a refusal says why.
    Outcome handle(const model::Action& action);
    // Each frame: polls a running load.
    void update();
    // The frame loop calls it while state() == Evolving (elsewhere it does nothing).
    model::StepResult evolve(int iterations);
    // Resume after a crash (workflow_resume.cpp): in Inspect, right after the autosave's scan
    // loaded and its level set went back into the engine. A session that was evolving comes
    // back paused: after a crash nothing moves until the operator says so. Undo starts empty.
    Outcome restoreSession(const RestoredSession& restored);

    [[nodiscard]] model::State state() const { return status_.state; }
    [[nodiscard]] const Status& status() const { return status_; }
    // Why a correction's own radius (voxels; <= 0: the brush's) typed by a person cannot be
    // taken on the loaded scan: outside the brush's range, to which a correction is clamped (a
    // robot's largest ball in the error may be), where a typed 1e9 must not silently become
    // the largest brush; "" when it can.
    [[nodiscard]] std::string correctionRadiusProblem(double radius) const;
    [[nodiscard]] bool quitRequested() const { return quit_; }
    [[nodiscard]] const Settings& settings() const { return settings_; }
    // The undo history's depth on each side, for tests and the soak's invariants.
    [[nodiscard]] std::size_t undoDepth() const { return undo_.undoDepth(); }
    [[nodiscard]] std::size_t redoDepth() const { return undo_.redoDepth(); }
    [[nodiscard]] std::size_t heldSnapshots() const { return undo_.snapshotCount(); }
    // The structures (the active one's mask empty: the engine's level set is its surface), for
    // the views that draw the others and for the autosave; its parameters as the workflow's now.
    [[nodiscard]] StructureList structures() const;
    // The same without a copy, the active one's record as it was when it became active: for a
    // view drawing the others each frame.
    [[nodiscard]] const StructureList& structureList() const { return structures_; }
    // Counts changes of the structures' list (masks, names, colours, visibility): the views
    // redraw the others on it.
    [[nodiscard]] std::uint64_t structuresVersion() const { return structuresVersion_; }

  private:
    static Outcome ok() { return {true, {}}; }
    static Outcome no(std::string reason) { return {false, std::move(reason)}; }

    // One handler per action, run once the transition table allowed it: the action's effect
    // (workflow.cpp: flow; workflow_params.cpp: parameters and probe; workflow_edits.cpp:
    // spheres, restart, undo; workflow_view.cpp: the view state). A handler may still refuse
    // the action's arguments.
    Outcome on(const model::LoadScan& a);
    Outcome on(const model::Probe& a);
    Outcome on(const model::ApplyPreset& a);
    Outcome on(const model::SetParam& a);
    Outcome on(const model::NudgeParam& a);
    Outcome on(const model::NudgeSelected& a);
    Outcome on(const model::SelectParam& a);
    Outcome on(const model::CycleParam& a);
    Outcome on(const model::SetWindow& a);
    Outcome on(const model::AddSeed& a);
    Outcome on(const model::Erase& a);
    Outcome on(const model::SetEraseMode& a);
    Outcome on(const model::SetSpeed& a);
    Outcome on(const model::MarkOutside& a);
    Outcome on(const model::ClearExamples& a);
    Outcome on(const model::SetOutsideMode& a);
    Outcome on(const model::PaintStroke& a); // workflow_strokes.cpp
    Outcome on(const model::Run& a);
    Outcome on(const model::Pause& a);
    Outcome on(const model::ToggleRun& a);
    Outcome on(const model::Finish& a);
    Outcome on(const model::Resume& a);
    Outcome on(const model::Export& a);
    Outcome on(const model::Undo& a);
    Outcome on(const model::Redo& a);
    Outcome on(const model::Restart& a);
    Outcome on(const model::Proceed& a);
    Outcome on(const model::Back& a);
    Outcome on(const model::Dismiss& a);
    Outcome on(const model::AcknowledgeAudit& a);
    Outcome on(const model::RotateView& a);
    Outcome on(const model::ZoomView& a);
    Outcome on(const model::PageSlice& a);
    Outcome on(const model::SetSlice& a);
    Outcome on(const model::ShowSlices& a);
    Outcome on(const model::Correct& a); // workflow_correct.cpp
    Outcome first(const model::Correct& a);
    Outcome on(const model::SetBox& a); // workflow_box.cpp
    Outcome on(const model::ClearBox& a);
    Outcome on(const model::SetBoxMode& a);
    // In box mode with a face chosen and a box: the box a knob's `steps` detents make of it
    // (one voxel a detent), else nothing and the knob drives the selected parameter.
    [[nodiscard]] std::optional<model::Box> knobBox(double steps) const;
    // Where the tissue that fills a first box lies, nearest its centre first: its probe, seed
    // and inside examples (workflow_box.cpp).
    [[nodiscard]] std::vector<glm::dvec3>
    boxTissueAt(const model::Box& box, const TissuePeak& tissue, double probeMm) const;
    // A seed beyond the box moves the box to hold it: the operator's seed outranks the box.
    void holdInBox(ParamValues& values, const model::Sphere& seed) const;
    // A correction's run moves the surface only near it (Settings::correctionReach); the
    // reach ends with the run, or when the speed or its parameters change.
    // recedeOutside: beyond the reach the surface only withdraws (model::Reach).
    void reachAround(const model::Sphere& brush, bool recedeOutside = false);
    // The sphere a correction's run may move the surface in; nullopt: everywhere.
    [[nodiscard]] std::optional<model::Sphere> reachOf(const model::Sphere& brush) const;
    void endReach();
    // An erase's run takes the surface back beyond the correction's reach at most
    // Settings::eraseWithdrawMm (model::WithdrawLimit) from the surface it left; endReach lifts
    // it, and so does any other change of the level set (an undo, an edit).
    void limitWithdrawal(const model::Sphere& brush);
    void liftWithdrawLimit();
    // An erase's run over the whole surface is watched (Settings::eraseRunGrowth): grown past
    // its limit, it is taken back to the erase and goes on withdrawing only beyond the reach,
    // and so do later erases' runs until T, eps, alpha or the kind of speed change.
    void watchEraseRun(const model::Sphere& brush, double volumeBeforeMl);
    // True when it took the run back.
    bool takeBackEraseRun();
    Outcome on(const model::Quit& a);
    // The PACS's (workflow_pacs.cpp): their arguments checked, nothing else here.
    Outcome on(const model::SearchPacs& a);
    Outcome on(const model::RetrievePacs& a);
    Outcome on(const model::CancelRetrieve& a);
    Outcome on(const model::ListPacsSeries& a);

    // The structures (workflow_structures.cpp).
    Outcome on(const model::EditStructure& a);
    Outcome addStructure(const std::string& name);
    // Makes `index` active: what the level set is now is kept as the one left's mask.
    Outcome selectStructure(std::size_t index, std::string_view what);
    Outcome deleteStructure(std::size_t index);
    Outcome describeStructure(const model::EditStructure& a, std::size_t index);
    // A new scan's one structure.
    void firstStructure();
    // The active structure as it is left now: its info, mask, parameters and counts.
    [[nodiscard]] Structure leaveActive() const;
    // The engine's barrier of the other structures' voxels (none where the config allows
    // overlap), for `list`'s active one.
    void claimOthers(const StructureList& list);
    // An undo entry's list put back (nothing for an entry of no structure change).
    void putStructures(const std::shared_ptr<const StructureList>& list);
    void showStructures();
    // Status::measurements of every structure with a surface (review's table and lines); one
    // the engine cannot measure is left out.
    void measureStructures();
    // Why `list` cannot be this scan's structures ("" when it can): a resume's check.
    [[nodiscard]] std::string structuresProblem(const StructureList& list) const;
    [[nodiscard]] bool hasResult() const; // a surface in any structure

    // States and transitions (workflow.cpp).
    void enter(model::State next, std::string message = {});
    [[nodiscard]] bool unexportedWork() const;
    // What the transition table's guards read.
    [[nodiscard]] Facts facts() const;
    // The undo flags and Status::allowed, after anything that may have changed them.
    void refreshAllowed();
    void finishLoad();
    void forgetScan();
    void noteAuditError();
    void record(const model::Action& action, model::State before, const Outcome& outcome);
    [[nodiscard]] nlohmann::json resultOf(const model::Action& action) const; // workflow_audit.cpp

    // Parameters (workflow_params.cpp).
    Outcome changeParams(ParamValues next, std::string_view what,
                         std::optional<model::Param> coalesce);
    // T and eps as a probe of `p` sets them (the probe's rule and the eps floor).
    void takeProbe(ParamValues& values, const ProbeResult& p) const;
    Outcome setParam(model::Param param, double value, std::string_view what);
    void applyParams(const ParamValues& values, bool force = false); // the engine, the status
    [[nodiscard]] ParamValues clamped(ParamValues values) const;
    [[nodiscard]] ParamValues defaultParams() const; // a new scan's or structure's
    void setDefaultParams();

    // The speed and the classifier's examples (workflow_speed.cpp).
    // What the engine runs for these values: Classify with an example of each kind, else the
    // fallback; the examples (and the window's bound, Settings::classifyWithinWindow) travel
    // only with Classify.
    [[nodiscard]] SpeedChoice speedFor(const ParamValues& values) const;
    // Settings::speedsOff's entry for `kind`, or null while it runs on this GPU.
    [[nodiscard]] const SpeedOff* speedOff(model::SpeedKind kind) const;
    // An example sphere in voxels for a probe-sized sphere in mm; nullopt outside the scan.
    [[nodiscard]] std::optional<model::Sphere> exampleAt(const glm::dvec3& voxel,
                                                         double radiusMm) const;
    void showSpeed(const ParamValues& values, model::SpeedKind inForce);
    // Appends, dropping the oldest past kMaxExamples.
    static void addExample(std::vector<model::Sphere>& examples, const model::Sphere& example);
    // Appends to SpeedChoice::painted*, dropping the oldest past kMaxPaintedExamples: a
    // stroke's dabs and the corrections' spheres, every one of which trains classify.
    static void addPainted(std::vector<model::Sphere>& painted,
                           const std::vector<model::Sphere>& spheres);

    // The level set (workflow_edits.cpp).
    // Why a sphere at `voxel` cannot be placed (a non-finite number, outside the scan), or "".
    [[nodiscard]] std::string sphereProblem(const glm::dvec3& voxel, double radius) const;
    // The sphere of an edit: `radius` voxels clamped to the brush's range, <= 0 the brush.
    [[nodiscard]] model::Sphere brushSphere(const glm::dvec3& voxel, double radius) const;
    Outcome sphereEdit(const glm::dvec3& voxel, double radius, bool seed);
    // A seed or an erase while steering (a correction): the edit and, when the engine has
    // room, a barrier that holds the sphere on its side (keeping or blocking). "" or why it
    // could not stick. A keeping one may carry its tissue's level (tissueLevel).
    std::string stickyEdit(const model::Sphere& sphere, bool seed,
                           const std::optional<model::TissueLevel>& tissue = std::nullopt);
    // The level of the tissue under a correction's seed and how far its window reaches
    // (model::TissueLevel); nullopt where corrections reach everywhere or the scan has no
    // finite value there.
    [[nodiscard]] std::optional<model::TissueLevel> tissueLevel(const model::Sphere& sphere) const;
    // `params`, when given, are applied after the edit and undone and redone with it: a seed's
    // inside example (applyEditParams).
    // `structures`: the lists before and after, for an edit that changes them.
    void editLevelSet(
        std::string_view what, const std::function<void()>& edit, int seeds, int erasures,
        const ParamValues* params = nullptr,
        std::pair<std::shared_ptr<const StructureList>, std::shared_ptr<const StructureList>>
            structures = {});
    // A level-set edit's parameters, on the edit, its undo and its redo, when they differ from
    // those in force; a refusal leaves the level set as it now is and says so.
    void applyEditParams(const ParamValues& values);
    LevelSetMark markNow(int seeds, int erasures);
    void restoreMark(const LevelSetMark& mark);
    void releaseSnapshot(const std::optional<SnapshotId>& id);
    void afterLevelSetChange();
    void refreshEngineStatus();
    void refreshUndoFlags();

    // Export (workflow_export.cpp).
    Outcome exportTo(const std::string& path);
    // The structures an export writes (engine's exportStructures), or none for a session that
    // holds one structure as a scan starts it: its level set alone, as before structures.
    [[nodiscard]] std::vector<ExportedStructure> exportedStructures() const;
    // <folder>/<scan>_<UTC time>, without an extension: the name no format's file has yet.
    [[nodiscard]] std::filesystem::path defaultExportBase() const;

    Engine& engine_;
    Settings settings_;
    AuditLog* audit_;
    UndoStack undo_;
    Status status_;
    ParamValues params_;      // as the status shows them (T, eps, alpha rounded to float)
    SpeedChoice engineSpeed_; // what the engine last accepted
    bool scanLoaded_ = false;
    bool dirty_ = false; // the level set changed since it was last exported
    bool quit_ = false;
    std::optional<model::Reach> reach_; // a correction's run's, while it lasts
    struct EraseRunWatch {
        model::Sphere brush;  // the erase's: its reach is where the run moves both ways after
        double limitMl = 0.0; // the volume it may not pass
        SnapshotId start = 0; // the surface the erase left (its undo entry's)
    };
    std::optional<EraseRunWatch> eraseWatch_; // an erase's global run's, while it lasts
    bool withdrawLimited_ = false;            // the engine holds a WithdrawLimit
    bool erasesCreep_ = false; // an erase's run went back under the speed now in force
    // Transitions made while handling one action, audited after the action's own record.
    struct PendingTransition {
        model::State from;
        model::State to;
        std::string message;
    };
    std::vector<PendingTransition> pending_;
    bool handling_ = false;
    std::string_view cause_; // the action being handled, or "load" / "evolve"
    ProbeResult lastProbe_;  // for the probe's audit record
    std::string lastUndone_; // what the last undo or redo took back or did again
    StructureList structures_;
    std::uint64_t structuresVersion_ = 0;
    std::string structureBefore_; // the active structure when the action being handled came
};

} // namespace steerseg::workflow
