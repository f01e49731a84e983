#pragma once

// The workflow's vocabulary: the states of the fixed operator workflow and the actions that
// move it. Devices, gestures, bindings and scripts all end here; nothing here knows where an
// action came from. No GL, no OS: the workflow runs in unit tests without a GPU.
#include "model/box.hpp"
#include "model/pacs_search.hpp"
#include "model/speed_kind.hpp"
#include "model/structure.hpp"

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace steerseg::model {

// load -> inspect -> seed -> evolve <-> pause (steering) -> review -> export -> done.
enum class State {
    NoScan,    // nothing loaded (start, or a load failed)
    Loading,   // a scan is being read off the frame loop
    Inspect,   // probe, window/level, presets, transfer function
    Seeding,   // place seed spheres (and erasers) before the first run
    Evolving,  // the solver runs; every parameter and sphere edit applies live
    Paused,    // steering with the solver stopped (also where convergence lands)
    Review,    // the operator looks at the result before exporting
    Exporting, // a write is under way
    Done,      // the result was written; a new scan may be loaded
    Error,     // something failed; the message says what, Dismiss goes back
};
std::string_view stateName(State state);

// The parameters a knob, the panel or a script can set. Radius is the brush (seed/erase sphere).
enum class Param { T, Eps, Alpha, Radius };
inline constexpr int kParamCount = 4;
std::string_view paramName(Param param); // "T", "eps", "alpha", "radius"
std::optional<Param> paramFromName(std::string_view name);

// Which 2D views the screen shows; the view state is the workflow's so scripts and the audit
// log see it, and a replay draws the same frames.
enum class SliceAxis { Axial, Coronal, Sagittal };
std::string_view sliceAxisName(SliceAxis axis); // "axial", "coronal", "sagittal"

// --- actions -------------------------------------------------------------------------------
struct LoadScan {
    std::string path; // a file, a DICOM folder or "builtin:sample"
};
struct Probe { // statistics of a sphere -> T and eps (with the eps floor)
    glm::dvec3 voxel{0.0};
    double radiusMm = 0.0; // <= 0: the config's [probe] radius_mm
};
struct ApplyPreset {
    std::string name; // a tissue preset of the config
};
struct SetParam { // absolute value, clamped to the parameter's range
    Param param = Param::T;
    double value = 0.0;
};
struct NudgeParam { // relative control: steps of the parameter's fine step (knobs, +/- keys)
    Param param = Param::T;
    double steps = 0.0;
};
struct NudgeSelected { // the same on the parameter a knob currently drives
    double steps = 0.0;
};
struct SelectParam { // absolute selection (panel) ...
    Param param = Param::T;
};
struct CycleParam { // ... or the next/previous one (a button)
    int delta = 1;
};
struct SetWindow {
    double level = 0.0;
    double width = 1.0;
};
struct AddSeed { // voxel-index centre, radius in voxels along the finest axis (Sphere)
    glm::dvec3 voxel{0.0};
    double radius = 0.0; // <= 0: the brush radius (Param::Radius)
};
struct Erase {
    glm::dvec3 voxel{0.0};
    double radius = 0.0; // <= 0: the brush radius
};
struct SetEraseMode { // a tap on a slice seeds, or erases in erase mode
    bool erase = false;
};
// The speed function (docs/speed.md). Classify learns from examples: the probes and the seeds
// are its inside examples, MarkOutside gives the outside ones (a tap in outside mode); the
// newest kMaxExamples of each kind count. Corrections while steering count as painted dabs do,
// all of them (workflow::SpeedChoice).
struct SetSpeed {
    model::SpeedKind kind = model::SpeedKind::Threshold;
};
struct MarkOutside {
    glm::dvec3 voxel{0.0};
    double radiusMm = 0.0; // <= 0: the probe's radius
};
struct ClearExamples {};
struct SetOutsideMode { // a tap on a slice marks an outside example in outside mode
    bool outside = false;
};
inline constexpr std::size_t kMaxExamples = 6; // three probes and three seeds, say
// A drag on a slice in add, erase or outside mode (docs/ui.md): the brush along the finger's
// path, as ITK-SNAP's, one undo step for the whole stroke. Add seeds and teaches classify inside,
// erase cuts, outside teaches classify outside; the classifier learns from every painted voxel
// (sampled), not only from the newest kMaxExamples taps. Points are voxel-index centres in the
// order the finger passed them; the workflow fills the gaps between successive ones.
enum class StrokeMode { Add, Erase, Outside };
std::string_view strokeModeName(StrokeMode mode); // "add", "erase", "outside"
std::optional<StrokeMode> strokeModeFromName(std::string_view name);
struct PaintStroke {
    StrokeMode mode = StrokeMode::Add;
    std::vector<glm::dvec3> points;
    double radius = 0.0; // voxels; <= 0: the brush radius (Param::Radius)
};
inline constexpr std::size_t kMaxStrokePoints = 4096; // the screen sends longer drags in pieces
struct Run {};
struct Pause {};
struct ToggleRun {}; // run if stopped, pause if running (a PowerMate press, the space bar)
struct Finish {};    // -> review
struct Resume {};    // review -> paused: back to steering
struct Export {
    std::string path; // empty: the export folder, a name from the scan and the time
};
struct Undo {};
struct Redo {};
struct Restart {}; // drop the level set and go back to seeding (undoable)
// The workflow's next and previous step, for a single button or pedal: inspect -> seeding ->
// evolving -> review -> export; back: seeding -> inspect, review -> paused, done -> review.
struct Proceed {};
struct Back {};
struct Dismiss {}; // acknowledge an error
// The operator knows the audit log cannot be written and exports anyway (recorded in the log
// once it can be written again); until then export is refused.
struct AcknowledgeAudit {};
// View state.
struct RotateView { // 3D view, degrees
    double yaw = 0.0;
    double pitch = 0.0;
};
struct ZoomView { // 3D view, factor (> 1 = closer)
    double factor = 1.0;
};
struct PageSlice { // a slice view, in slices
    SliceAxis axis = SliceAxis::Axial;
    int delta = 0;
};
struct SetSlice {
    SliceAxis axis = SliceAxis::Axial;
    int index = 0;
};
struct ShowSlices { // which two orientations the slice views show
    SliceAxis first = SliceAxis::Axial;
    SliceAxis second = SliceAxis::Coronal;
};
// The operator's correction tap, as the clicks protocol counts it (docs/steering.md): a tap in
// add mode (positive) or remove mode (negative) that the surface should follow at once. The
// first one, on a scan without a level set, probes and seeds there; after it a positive one is
// a seed, a negative one an erase that sticks (a barrier and an outside example). Either way
// the solver then runs from the current surface: AddSeed or Erase and Run, one undo step.
struct Correct {
    glm::dvec3 voxel{0.0};
    bool positive = true;
    double radius = 0.0; // voxels; <= 0: the brush radius
};
// The operator's box (model::Box, docs/steering.md "The box"): the surface stays in it. On a
// scan without a level set it also probes and seeds at its centre; a later one moves it, and
// the surface follows. One undo step either way; ClearBox lets the surface go anywhere again.
struct SetBox {
    Box box;
};
struct ClearBox {};
// Box mode (docs/ui.md): a drag on a slice draws or moves the box; a tap places nothing. It
// excludes erase and outside modes (one meaning per tap). `face`: the face a knob detent then
// moves (NudgeSelected, one voxel a detent), the one the operator last dragged; none: the
// knob drives the selected parameter.
struct SetBoxMode {
    bool on = false;
    std::optional<BoxFace> face;
};
// The session's structures (model::StructureInfo, docs/structures.md). Add: the active one is
// kept as it stands, as a mask, and a new empty one becomes active; select: the named one
// becomes active again, its surface and parameters back; rename, recolour, show and hide change
// how the views and the exports name and draw it; delete drops it (deleting the active one
// makes the one before it active). One undo step each.
enum class StructureOp { Add, Select, Rename, Recolour, Show, Hide, Delete };
std::string_view structureOpName(StructureOp op); // "add", "select", "rename", ...
std::optional<StructureOp> structureOpFromName(std::string_view name);
struct EditStructure {
    StructureOp op = StructureOp::Add;
    std::string name;       // the structure it names (add: the new one's name)
    std::string to;         // rename: the new name
    glm::dvec3 colour{0.0}; // recolour: r g b within 0..1
};
// The PACS (docs/dicom-network.md "The kiosk's search"): the workflow takes them in every state
// (they touch no scan) so that scripts drive them and the audit log records them; the kiosk's
// DICOM node asks the network. `peer`: a [[dicom.peers]] name with query = true ("" = the first).
struct SearchPacs {
    std::string peer;
    PacsKeys keys;
};
struct ListPacsSeries { // the series of a study a search found, for a retrieve of one
    std::string peer;
    std::string studyUid;
};
struct RetrievePacs { // a study, or one of its series, into the incoming store
    std::string peer;
    std::string studyUid;
    std::string seriesUid; // "" = the whole study
};
struct CancelRetrieve {};
struct Quit {};

using Action =
    std::variant<LoadScan, Probe, ApplyPreset, SetParam, NudgeParam, NudgeSelected, SelectParam,
                 CycleParam, SetWindow, AddSeed, Erase, SetEraseMode, SetSpeed, MarkOutside,
                 ClearExamples, SetOutsideMode, PaintStroke, Run, Pause, ToggleRun, Finish, Resume,
                 Export, Undo, Redo, Restart, Proceed, Back, Dismiss, AcknowledgeAudit, RotateView,
                 ZoomView, PageSlice, SetSlice, ShowSlices, Correct, SetBox, ClearBox, SetBoxMode,
                 EditStructure, SearchPacs, ListPacsSeries, RetrievePacs, CancelRetrieve, Quit>;

// "load_scan", "probe", ... (snake_case of the type): the audit log's and scripts' names.
std::string_view actionName(const Action& action);

// An action's type without its arguments, in the variant's order (action.cpp checks each), so
// the transition table and Status::allowed can name what may happen without a value.
enum class ActionKind {
    LoadScan,
    Probe,
    ApplyPreset,
    SetParam,
    NudgeParam,
    NudgeSelected,
    SelectParam,
    CycleParam,
    SetWindow,
    AddSeed,
    Erase,
    SetEraseMode,
    SetSpeed,
    MarkOutside,
    ClearExamples,
    SetOutsideMode,
    PaintStroke,
    Run,
    Pause,
    ToggleRun,
    Finish,
    Resume,
    Export,
    Undo,
    Redo,
    Restart,
    Proceed,
    Back,
    Dismiss,
    AcknowledgeAudit,
    RotateView,
    ZoomView,
    PageSlice,
    SetSlice,
    ShowSlices,
    Correct,
    SetBox,
    ClearBox,
    SetBoxMode,
    EditStructure,
    SearchPacs,
    ListPacsSeries,
    RetrievePacs,
    CancelRetrieve,
    Quit,
};
inline constexpr std::size_t kActionKindCount = std::variant_size_v<Action>;
ActionKind kindOf(const Action& action);
std::string_view actionKindName(ActionKind kind); // actionName's word for the kind

class ActionKinds {
  public:
    constexpr ActionKinds() = default;
    constexpr ActionKinds(std::initializer_list<ActionKind> kinds) {
        for (const ActionKind k : kinds) {
            insert(k);
        }
    }
    constexpr void insert(ActionKind kind) { bits_ |= bit(kind); }
    constexpr void insert(ActionKinds kinds) { bits_ |= kinds.bits_; }
    [[nodiscard]] constexpr bool contains(ActionKind kind) const {
        return (bits_ & bit(kind)) != 0;
    }
    [[nodiscard]] constexpr bool empty() const { return bits_ == 0; }
    friend constexpr bool operator==(ActionKinds, ActionKinds) = default;

  private:
    static constexpr std::uint64_t bit(ActionKind kind) {
        return std::uint64_t{1} << static_cast<unsigned>(kind);
    }
    std::uint64_t bits_ = 0;
};
static_assert(kActionKindCount <= 64, "ActionKinds holds one bit per kind");

// The actions a binding can name (config's [bindings]): the ones without arguments, plus the
// relative ones with a step ("nudge:T", "nudge_selected", "page:axial", "rotate_yaw", ...).
// Returns the action for one step of the control (`steps` = signed detents or key repeats).
// nullopt for a name that is not bindable (or a step that is not finite); bindableNames() lists
// them for the config's message.
std::optional<Action> bindingAction(std::string_view name, double steps);
// Whether a binding may name `name`: config's BindingCheck wherever the config is read.
bool isBindable(std::string_view name);
const std::vector<std::string_view>& bindableNames();

} // namespace steerseg::model
