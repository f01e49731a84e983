// What an accepted action changed, for its audit record's "result": the values it set after
// clamping (the action's own "values" are what was asked for).
#include "model/speed_kind.hpp"
#include "workflow/workflow.hpp"

#include <array>
#include <charconv>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <system_error>
#include <type_traits>

namespace steerseg::workflow {

namespace {

template <class T, class... U> constexpr bool isOneOf = (std::is_same_v<T, U> || ...);

// The solver's floats as the shortest decimals that read back as them (0.8, not
// 0.800000011920929): what the panel shows is what the log says.
double decimal(float f) {
    std::array<char, 32> buf{};
    const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size() - 1, f);
    if (ec != std::errc()) {
        return static_cast<double>(f);
    }
    *end = '\0';
    return std::strtod(buf.data(), nullptr);
}

} // namespace

nlohmann::json Workflow::resultOf(const model::Action& action) const {
    const auto params = [this] {
        nlohmann::json p{{"T", decimal(status_.params.T)},
                         {"eps", decimal(status_.params.eps)},
                         {"alpha", decimal(status_.params.alpha)},
                         {"radius", status_.radius}};
        if (!status_.preset.empty()) {
            p["preset"] = status_.preset;
        }
        return p;
    };
    const auto levelSet = [this] {
        return nlohmann::json{{"seeds", status_.seeds},
                              {"erasures", status_.erasures},
                              {"has_level_set", status_.hasLevelSet},
                              {"volume_ml", status_.volumeMl}};
    };
    // The speed as chosen and as the engine runs it (they differ while classify waits).
    const auto speed = [this] {
        return nlohmann::json{{"speed", model::speedKindName(status_.speed)},
                              {"speed_in_force", model::speedKindName(status_.speedInForce)},
                              {"inside_examples", status_.insideExamples.size()},
                              {"outside_examples", status_.outsideExamples.size()}};
    };
    const ViewState& v = status_.view;
    return std::visit(
        [&](const auto& a) -> nlohmann::json {
            using A = std::decay_t<decltype(a)>;
            if constexpr (std::is_same_v<A, model::Probe>) {
                nlohmann::json r = params();
                r["mean"] = lastProbe_.mean;
                r["stddev"] = lastProbe_.stddev;
                r["count"] = lastProbe_.count;
                r["left_out"] = lastProbe_.leftOut;
                r.update(speed());
                return r;
            } else if constexpr (std::is_same_v<A, model::ApplyPreset>) {
                nlohmann::json r = params();
                r["window_level"] = v.windowLevel;
                r["window_width"] = v.windowWidth;
                r["transfer"] = v.transfer;
                return r;
            } else if constexpr (isOneOf<A, model::SetParam, model::NudgeParam>) {
                return params();
            } else if constexpr (std::is_same_v<A, model::NudgeSelected>) {
                // In box mode the knob may have moved a face of the box (Workflow::knobBox).
                nlohmann::json r = params();
                if (status_.box) {
                    r["box"] = boxValues(*status_.box);
                }
                return r;
            } else if constexpr (isOneOf<A, model::AddSeed, model::Erase, model::Restart>) {
                return levelSet();
            } else if constexpr (std::is_same_v<A, model::Correct>) {
                nlohmann::json r = params();
                r.update(levelSet());
                r["barriers"] = engine_.barriers();
                r["reach"] = reach_ ? nlohmann::json(reach_->sphere.radius) : nlohmann::json();
                return r;
            } else if constexpr (isOneOf<A, model::SetBox, model::ClearBox>) {
                // The box in force after it: a seed beyond a box moves it, so the record of
                // the action alone would not say where it is.
                nlohmann::json r = params();
                r.update(levelSet());
                r.update(speed());
                r["box"] = status_.box ? boxValues(*status_.box) : nlohmann::json();
                return r;
            } else if constexpr (std::is_same_v<A, model::PaintStroke>) {
                nlohmann::json r = levelSet();
                r.update(speed());
                r["painted_inside"] = status_.paintedInside.size();
                r["painted_outside"] = status_.paintedOutside.size();
                return r;
            } else if constexpr (isOneOf<A, model::Undo, model::Redo>) {
                nlohmann::json r = params();
                r.update(levelSet());
                r.update(speed());
                r["entry"] = lastUndone_;
                return r;
            } else if constexpr (isOneOf<A, model::SetSpeed, model::MarkOutside,
                                         model::ClearExamples>) {
                return speed();
            } else if constexpr (std::is_same_v<A, model::SetOutsideMode>) {
                return {{"outside_mode", status_.outsideMode}, {"erase_mode", status_.eraseMode}};
            } else if constexpr (std::is_same_v<A, model::SetBoxMode>) {
                return {{"box_mode", status_.boxMode},
                        {"outside_mode", status_.outsideMode},
                        {"erase_mode", status_.eraseMode}};
            } else if constexpr (isOneOf<A, model::SelectParam, model::CycleParam>) {
                return {{"selected", model::paramName(status_.selected)}};
            } else if constexpr (isOneOf<A, model::Export, model::Proceed>) {
                if (status_.state == model::State::Done && !status_.exportedPath.empty()) {
                    // Every file, not only the first: a DICOM SEG's measurement report too.
                    return {{"exported", status_.exportedPath}, {"files", status_.exportedFiles}};
                }
                return nullptr;
            } else if constexpr (std::is_same_v<A, model::EditStructure>) {
                // The list after it, and the surface now in force (a select's or delete's).
                nlohmann::json list = nlohmann::json::array();
                for (const StructureRow& s : status_.structures) {
                    list.push_back({{"name", s.info.name},
                                    {"volume_ml", s.volumeMl},
                                    {"visible", s.info.visible},
                                    {"active", s.active}});
                }
                nlohmann::json r = levelSet();
                r["structures"] = std::move(list);
                return r;
            } else if constexpr (std::is_same_v<A, model::SetWindow>) {
                return {{"window_level", v.windowLevel}, {"window_width", v.windowWidth}};
            } else if constexpr (isOneOf<A, model::RotateView, model::ZoomView>) {
                return {{"yaw", v.yawDeg}, {"pitch", v.pitchDeg}, {"zoom", v.zoom}};
            } else if constexpr (isOneOf<A, model::PageSlice, model::SetSlice>) {
                return {{"slice", {v.slice.x, v.slice.y, v.slice.z}}};
            } else {
                return nullptr;
            }
        },
        action);
}

} // namespace steerseg::workflow
