#include "model/action.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

namespace steerseg::model {

namespace {

constexpr std::array<std::string_view, kParamCount> kParamNames{"T", "eps", "alpha", "radius"};
// In StrokeMode's order.
constexpr std::array<std::string_view, 3> kStrokeModeNames{"add", "erase", "outside"};
// In StructureOp's order.
constexpr std::array<std::string_view, 7> kStructureOpNames{"add",  "select", "rename", "recolour",
                                                            "show", "hide",   "delete"};

// Knobs and keys deliver detents; these turn one detent into the view's own units.
constexpr double kRotateDegreesPerStep = 5.0;
constexpr double kZoomPerStep = 1.1;

// A whole number of detents for the integer-valued actions, at least one in the step's
// direction (a fractional wheel delta still moves) and bounded (a flood of repeats is not UB).
int wholeSteps(double steps) {
    const double bounded = std::clamp(steps, -1.0e6, 1.0e6);
    const double rounded = std::round(bounded);
    if (rounded == 0.0 && bounded != 0.0) {
        return bounded > 0.0 ? 1 : -1;
    }
    return static_cast<int>(rounded);
}

template <class T> constexpr std::string_view nameOf() {
    if constexpr (std::is_same_v<T, LoadScan>) {
        return "load_scan";
    } else if constexpr (std::is_same_v<T, Probe>) {
        return "probe";
    } else if constexpr (std::is_same_v<T, ApplyPreset>) {
        return "apply_preset";
    } else if constexpr (std::is_same_v<T, SetParam>) {
        return "set_param";
    } else if constexpr (std::is_same_v<T, NudgeParam>) {
        return "nudge_param";
    } else if constexpr (std::is_same_v<T, NudgeSelected>) {
        return "nudge_selected";
    } else if constexpr (std::is_same_v<T, SelectParam>) {
        return "select_param";
    } else if constexpr (std::is_same_v<T, CycleParam>) {
        return "cycle_param";
    } else if constexpr (std::is_same_v<T, SetWindow>) {
        return "set_window";
    } else if constexpr (std::is_same_v<T, AddSeed>) {
        return "add_seed";
    } else if constexpr (std::is_same_v<T, Erase>) {
        return "erase";
    } else if constexpr (std::is_same_v<T, SetEraseMode>) {
        return "set_erase_mode";
    } else if constexpr (std::is_same_v<T, SetSpeed>) {
        return "set_speed";
    } else if constexpr (std::is_same_v<T, MarkOutside>) {
        return "mark_outside";
    } else if constexpr (std::is_same_v<T, ClearExamples>) {
        return "clear_examples";
    } else if constexpr (std::is_same_v<T, SetOutsideMode>) {
        return "set_outside_mode";
    } else if constexpr (std::is_same_v<T, PaintStroke>) {
        return "paint_stroke";
    } else if constexpr (std::is_same_v<T, Run>) {
        return "run";
    } else if constexpr (std::is_same_v<T, Pause>) {
        return "pause";
    } else if constexpr (std::is_same_v<T, ToggleRun>) {
        return "toggle_run";
    } else if constexpr (std::is_same_v<T, Finish>) {
        return "finish";
    } else if constexpr (std::is_same_v<T, Resume>) {
        return "resume";
    } else if constexpr (std::is_same_v<T, Export>) {
        return "export";
    } else if constexpr (std::is_same_v<T, Undo>) {
        return "undo";
    } else if constexpr (std::is_same_v<T, Redo>) {
        return "redo";
    } else if constexpr (std::is_same_v<T, Restart>) {
        return "restart";
    } else if constexpr (std::is_same_v<T, Proceed>) {
        return "proceed";
    } else if constexpr (std::is_same_v<T, Back>) {
        return "back";
    } else if constexpr (std::is_same_v<T, Dismiss>) {
        return "dismiss";
    } else if constexpr (std::is_same_v<T, AcknowledgeAudit>) {
        return "acknowledge_audit";
    } else if constexpr (std::is_same_v<T, RotateView>) {
        return "rotate_view";
    } else if constexpr (std::is_same_v<T, ZoomView>) {
        return "zoom_view";
    } else if constexpr (std::is_same_v<T, PageSlice>) {
        return "page_slice";
    } else if constexpr (std::is_same_v<T, SetSlice>) {
        return "set_slice";
    } else if constexpr (std::is_same_v<T, ShowSlices>) {
        return "show_slices";
    } else if constexpr (std::is_same_v<T, Correct>) {
        return "correct";
    } else if constexpr (std::is_same_v<T, SetBox>) {
        return "set_box";
    } else if constexpr (std::is_same_v<T, ClearBox>) {
        return "clear_box";
    } else if constexpr (std::is_same_v<T, SetBoxMode>) {
        return "set_box_mode";
    } else if constexpr (std::is_same_v<T, EditStructure>) {
        return "edit_structure";
    } else if constexpr (std::is_same_v<T, SearchPacs>) {
        return "search_pacs";
    } else if constexpr (std::is_same_v<T, RetrievePacs>) {
        return "retrieve_pacs";
    } else if constexpr (std::is_same_v<T, CancelRetrieve>) {
        return "cancel_retrieve";
    } else if constexpr (std::is_same_v<T, ListPacsSeries>) {
        return "list_pacs_series";
    } else {
        static_assert(std::is_same_v<T, Quit>, "every action needs a name");
        return "quit";
    }
}

using Maker = Action (*)(double steps);

struct Binding {
    std::string_view name;
    Maker make;
};

// One table for both lookups, so bindableNames() cannot list a name bindingAction() refuses.
const std::vector<Binding>& bindings() {
    static const std::vector<Binding> table{
        {"run", [](double) -> Action { return Run{}; }},
        {"pause", [](double) -> Action { return Pause{}; }},
        {"toggle_run", [](double) -> Action { return ToggleRun{}; }},
        {"finish", [](double) -> Action { return Finish{}; }},
        {"resume", [](double) -> Action { return Resume{}; }},
        {"export", [](double) -> Action { return Export{}; }},
        {"undo", [](double) -> Action { return Undo{}; }},
        {"redo", [](double) -> Action { return Redo{}; }},
        {"restart", [](double) -> Action { return Restart{}; }},
        {"proceed", [](double) -> Action { return Proceed{}; }},
        {"back", [](double) -> Action { return Back{}; }},
        {"dismiss", [](double) -> Action { return Dismiss{}; }},
        {"acknowledge_audit", [](double) -> Action { return AcknowledgeAudit{}; }},
        {"quit", [](double) -> Action { return Quit{}; }},
        {"cancel_retrieve", [](double) -> Action { return CancelRetrieve{}; }},
        {"erase_mode:on", [](double) -> Action { return SetEraseMode{true}; }},
        {"erase_mode:off", [](double) -> Action { return SetEraseMode{false}; }},
        {"speed:threshold", [](double) -> Action { return SetSpeed{model::SpeedKind::Threshold}; }},
        {"speed:edge", [](double) -> Action { return SetSpeed{model::SpeedKind::Edge}; }},
        {"speed:classify", [](double) -> Action { return SetSpeed{model::SpeedKind::Classify}; }},
        {"outside_mode:on", [](double) -> Action { return SetOutsideMode{true}; }},
        {"outside_mode:off", [](double) -> Action { return SetOutsideMode{false}; }},
        {"clear_examples", [](double) -> Action { return ClearExamples{}; }},
        {"select:T", [](double) -> Action { return SelectParam{Param::T}; }},
        {"select:eps", [](double) -> Action { return SelectParam{Param::Eps}; }},
        {"select:alpha", [](double) -> Action { return SelectParam{Param::Alpha}; }},
        {"select:radius", [](double) -> Action { return SelectParam{Param::Radius}; }},
        {"cycle_param", [](double s) -> Action { return CycleParam{wholeSteps(s)}; }},
        {"nudge:T",
         [](double s) -> Action {
             return NudgeParam{Param::T, s};
         }},
        {"nudge:eps",
         [](double s) -> Action {
             return NudgeParam{Param::Eps, s};
         }},
        {"nudge:alpha",
         [](double s) -> Action {
             return NudgeParam{Param::Alpha, s};
         }},
        {"nudge:radius",
         [](double s) -> Action {
             return NudgeParam{Param::Radius, s};
         }},
        {"nudge_selected", [](double s) -> Action { return NudgeSelected{s}; }},
        {"page:axial",
         [](double s) -> Action {
             return PageSlice{SliceAxis::Axial, wholeSteps(s)};
         }},
        {"page:coronal",
         [](double s) -> Action {
             return PageSlice{SliceAxis::Coronal, wholeSteps(s)};
         }},
        {"page:sagittal",
         [](double s) -> Action {
             return PageSlice{SliceAxis::Sagittal, wholeSteps(s)};
         }},
        {"rotate_yaw",
         [](double s) -> Action {
             return RotateView{s * kRotateDegreesPerStep, 0.0};
         }},
        {"rotate_pitch",
         [](double s) -> Action {
             return RotateView{0.0, s * kRotateDegreesPerStep};
         }},
        {"zoom", [](double s) -> Action { return ZoomView{std::pow(kZoomPerStep, s)}; }},
    };
    return table;
}

} // namespace

std::string_view stateName(State state) {
    switch (state) {
    case State::NoScan:
        return "no_scan";
    case State::Loading:
        return "loading";
    case State::Inspect:
        return "inspect";
    case State::Seeding:
        return "seeding";
    case State::Evolving:
        return "evolving";
    case State::Paused:
        return "paused";
    case State::Review:
        return "review";
    case State::Exporting:
        return "exporting";
    case State::Done:
        return "done";
    case State::Error:
        return "error";
    }
    return "unknown";
}

std::string_view paramName(Param param) {
    const auto i = static_cast<std::size_t>(param);
    return i < kParamNames.size() ? kParamNames[i] : std::string_view("unknown");
}

std::optional<Param> paramFromName(std::string_view name) {
    for (std::size_t i = 0; i < kParamNames.size(); ++i) {
        if (kParamNames[i] == name) {
            return static_cast<Param>(i);
        }
    }
    return std::nullopt;
}

std::string_view sliceAxisName(SliceAxis axis) {
    switch (axis) {
    case SliceAxis::Axial:
        return "axial";
    case SliceAxis::Coronal:
        return "coronal";
    case SliceAxis::Sagittal:
        return "sagittal";
    }
    return "unknown";
}

std::string_view strokeModeName(StrokeMode mode) {
    const auto i = static_cast<std::size_t>(mode);
    return i < kStrokeModeNames.size() ? kStrokeModeNames[i] : std::string_view("unknown");
}

std::optional<StrokeMode> strokeModeFromName(std::string_view name) {
    const auto* at = std::find(kStrokeModeNames.begin(), kStrokeModeNames.end(), name);
    if (at == kStrokeModeNames.end()) {
        return std::nullopt;
    }
    return static_cast<StrokeMode>(at - kStrokeModeNames.begin());
}

std::string_view actionName(const Action& action) {
    return std::visit([](const auto& a) { return nameOf<std::decay_t<decltype(a)>>(); }, action);
}

namespace {

template <ActionKind K>
using TypeOf = std::variant_alternative_t<static_cast<std::size_t>(K), Action>;
// A reordered variant or enum would make every table row mean another action.
static_assert(std::is_same_v<TypeOf<ActionKind::LoadScan>, LoadScan>);
static_assert(std::is_same_v<TypeOf<ActionKind::Probe>, Probe>);
static_assert(std::is_same_v<TypeOf<ActionKind::ApplyPreset>, ApplyPreset>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetParam>, SetParam>);
static_assert(std::is_same_v<TypeOf<ActionKind::NudgeParam>, NudgeParam>);
static_assert(std::is_same_v<TypeOf<ActionKind::NudgeSelected>, NudgeSelected>);
static_assert(std::is_same_v<TypeOf<ActionKind::SelectParam>, SelectParam>);
static_assert(std::is_same_v<TypeOf<ActionKind::CycleParam>, CycleParam>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetWindow>, SetWindow>);
static_assert(std::is_same_v<TypeOf<ActionKind::AddSeed>, AddSeed>);
static_assert(std::is_same_v<TypeOf<ActionKind::Erase>, Erase>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetEraseMode>, SetEraseMode>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetSpeed>, SetSpeed>);
static_assert(std::is_same_v<TypeOf<ActionKind::MarkOutside>, MarkOutside>);
static_assert(std::is_same_v<TypeOf<ActionKind::ClearExamples>, ClearExamples>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetOutsideMode>, SetOutsideMode>);
static_assert(std::is_same_v<TypeOf<ActionKind::PaintStroke>, PaintStroke>);
static_assert(std::is_same_v<TypeOf<ActionKind::Run>, Run>);
static_assert(std::is_same_v<TypeOf<ActionKind::Pause>, Pause>);
static_assert(std::is_same_v<TypeOf<ActionKind::ToggleRun>, ToggleRun>);
static_assert(std::is_same_v<TypeOf<ActionKind::Finish>, Finish>);
static_assert(std::is_same_v<TypeOf<ActionKind::Resume>, Resume>);
static_assert(std::is_same_v<TypeOf<ActionKind::Export>, Export>);
static_assert(std::is_same_v<TypeOf<ActionKind::Undo>, Undo>);
static_assert(std::is_same_v<TypeOf<ActionKind::Redo>, Redo>);
static_assert(std::is_same_v<TypeOf<ActionKind::Restart>, Restart>);
static_assert(std::is_same_v<TypeOf<ActionKind::Proceed>, Proceed>);
static_assert(std::is_same_v<TypeOf<ActionKind::Back>, Back>);
static_assert(std::is_same_v<TypeOf<ActionKind::Dismiss>, Dismiss>);
static_assert(std::is_same_v<TypeOf<ActionKind::AcknowledgeAudit>, AcknowledgeAudit>);
static_assert(std::is_same_v<TypeOf<ActionKind::RotateView>, RotateView>);
static_assert(std::is_same_v<TypeOf<ActionKind::ZoomView>, ZoomView>);
static_assert(std::is_same_v<TypeOf<ActionKind::PageSlice>, PageSlice>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetSlice>, SetSlice>);
static_assert(std::is_same_v<TypeOf<ActionKind::ShowSlices>, ShowSlices>);
static_assert(std::is_same_v<TypeOf<ActionKind::Correct>, Correct>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetBox>, SetBox>);
static_assert(std::is_same_v<TypeOf<ActionKind::ClearBox>, ClearBox>);
static_assert(std::is_same_v<TypeOf<ActionKind::SetBoxMode>, SetBoxMode>);
static_assert(std::is_same_v<TypeOf<ActionKind::EditStructure>, EditStructure>);
static_assert(std::is_same_v<TypeOf<ActionKind::SearchPacs>, SearchPacs>);
static_assert(std::is_same_v<TypeOf<ActionKind::RetrievePacs>, RetrievePacs>);
static_assert(std::is_same_v<TypeOf<ActionKind::CancelRetrieve>, CancelRetrieve>);
static_assert(std::is_same_v<TypeOf<ActionKind::ListPacsSeries>, ListPacsSeries>);
static_assert(std::is_same_v<TypeOf<ActionKind::Quit>, Quit>);
static_assert(static_cast<std::size_t>(ActionKind::Quit) + 1 == kActionKindCount);

template <std::size_t... I>
constexpr std::array<std::string_view, kActionKindCount> kindNames(std::index_sequence<I...>) {
    return {nameOf<std::variant_alternative_t<I, Action>>()...};
}

constexpr auto kKindNames = kindNames(std::make_index_sequence<kActionKindCount>{});

} // namespace

std::string_view structureOpName(StructureOp op) {
    return kStructureOpNames.at(static_cast<std::size_t>(op));
}

std::optional<StructureOp> structureOpFromName(std::string_view name) {
    for (std::size_t i = 0; i < kStructureOpNames.size(); ++i) {
        if (kStructureOpNames[i] == name) {
            return static_cast<StructureOp>(i);
        }
    }
    return std::nullopt;
}

ActionKind kindOf(const Action& action) {
    return static_cast<ActionKind>(action.index());
}

std::string_view actionKindName(ActionKind kind) {
    const auto i = static_cast<std::size_t>(kind);
    return i < kKindNames.size() ? kKindNames[i] : std::string_view("?");
}

bool isBindable(std::string_view name) {
    return bindingAction(name, 1.0).has_value();
}

std::optional<Action> bindingAction(std::string_view name, double steps) {
    // A NaN or infinite step has no meaning for any control; the caller names the binding.
    if (!std::isfinite(steps)) {
        return std::nullopt;
    }
    for (const Binding& b : bindings()) {
        if (b.name == name) {
            return b.make(steps);
        }
    }
    return std::nullopt;
}

const std::vector<std::string_view>& bindableNames() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (const Binding& b : bindings()) {
            out.push_back(b.name);
        }
        return out;
    }();
    return names;
}

} // namespace steerseg::model
