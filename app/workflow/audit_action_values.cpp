// The audit log's "values" of each action (workflow/audit_log.hpp, actionValues): what the
// operator asked for, in the JSON a reviewer reads; a stroke's path thinned, nothing else left
// out.
#include "model/speed_kind.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <type_traits>
#include <variant>

namespace steerseg::workflow {

namespace {

nlohmann::json vec(const glm::dvec3& v) {
    return nlohmann::json::array({v.x, v.y, v.z});
}

nlohmann::json values(const model::LoadScan& a) {
    return {{"path", a.path}};
}
nlohmann::json values(const model::Probe& a) {
    return {{"voxel", vec(a.voxel)}, {"radius_mm", a.radiusMm}};
}
nlohmann::json values(const model::ApplyPreset& a) {
    return {{"name", a.name}};
}
nlohmann::json values(const model::SetParam& a) {
    return {{"param", model::paramName(a.param)}, {"value", a.value}};
}
nlohmann::json values(const model::NudgeParam& a) {
    return {{"param", model::paramName(a.param)}, {"steps", a.steps}};
}
nlohmann::json values(const model::NudgeSelected& a) {
    return {{"steps", a.steps}};
}
nlohmann::json values(const model::SelectParam& a) {
    return {{"param", model::paramName(a.param)}};
}
nlohmann::json values(const model::CycleParam& a) {
    return {{"delta", a.delta}};
}
nlohmann::json values(const model::SetWindow& a) {
    return {{"level", a.level}, {"width", a.width}};
}
nlohmann::json values(const model::AddSeed& a) {
    return {{"voxel", vec(a.voxel)}, {"radius", a.radius}};
}
nlohmann::json values(const model::Erase& a) {
    return {{"voxel", vec(a.voxel)}, {"radius", a.radius}};
}
nlohmann::json values(const model::Correct& a) {
    return {{"voxel", vec(a.voxel)}, {"positive", a.positive}, {"radius", a.radius}};
}
nlohmann::json values(const model::SetEraseMode& a) {
    return {{"erase", a.erase}};
}
nlohmann::json values(const model::SetSpeed& a) {
    return {{"speed", model::speedKindName(a.kind)}};
}
nlohmann::json values(const model::MarkOutside& a) {
    return {{"voxel", vec(a.voxel)}, {"radius_mm", a.radiusMm}};
}
nlohmann::json values(const model::SetOutsideMode& a) {
    return {{"outside", a.outside}};
}
// A stroke's path, evenly thinned to at most this many points (the first and the last kept): a
// long scribble must not make a line of the log megabytes long.
constexpr std::size_t kLoggedStrokePoints = 256;
nlohmann::json values(const model::PaintStroke& a) {
    nlohmann::json points = nlohmann::json::array();
    const std::size_t n = a.points.size();
    const std::size_t logged = std::min(n, kLoggedStrokePoints);
    for (std::size_t i = 0; i < logged; ++i) {
        points.push_back(vec(a.points[logged < 2 ? i : i * (n - 1) / (logged - 1)]));
    }
    return {{"mode", model::strokeModeName(a.mode)},
            {"radius", a.radius},
            {"point_count", n},
            {"points", points}};
}
nlohmann::json values(const model::Export& a) {
    return {{"path", a.path}};
}
nlohmann::json values(const model::RotateView& a) {
    return {{"yaw", a.yaw}, {"pitch", a.pitch}};
}
nlohmann::json values(const model::ZoomView& a) {
    return {{"factor", a.factor}};
}
nlohmann::json values(const model::PageSlice& a) {
    return {{"axis", model::sliceAxisName(a.axis)}, {"delta", a.delta}};
}
nlohmann::json values(const model::SetSlice& a) {
    return {{"axis", model::sliceAxisName(a.axis)}, {"index", a.index}};
}
nlohmann::json values(const model::ShowSlices& a) {
    return {{"first", model::sliceAxisName(a.first)}, {"second", model::sliceAxisName(a.second)}};
}
nlohmann::json values(const model::SetBox& a) {
    return boxValues(a.box);
}
nlohmann::json values(const model::SetBoxMode& a) {
    nlohmann::json v{{"on", a.on}};
    if (a.face) {
        v["face"] = {{"axis", a.face->axis}, {"high", a.face->high}};
    }
    return v;
}
nlohmann::json values(const model::EditStructure& a) {
    nlohmann::json v{{"op", model::structureOpName(a.op)}, {"name", a.name}};
    if (a.op == model::StructureOp::Rename) {
        v["to"] = a.to;
    } else if (a.op == model::StructureOp::Recolour) {
        v["colour"] = {a.colour.r, a.colour.g, a.colour.b};
    }
    return v;
}
nlohmann::json values(const model::SearchPacs& a) {
    nlohmann::json v{{"peer", a.peer}};
    for (std::size_t i = 0; i < model::kSearchFieldCount; ++i) {
        const auto field = static_cast<model::SearchField>(i);
        if (const std::string& key = model::keyOf(a.keys, field); !key.empty()) {
            v[std::string(model::searchFieldName(field))] = key;
        }
    }
    return v;
}
nlohmann::json values(const model::RetrievePacs& a) {
    return {{"peer", a.peer}, {"study", a.studyUid}, {"series", a.seriesUid}};
}
nlohmann::json values(const model::ListPacsSeries& a) {
    return {{"peer", a.peer}, {"study", a.studyUid}};
}
template <class T> nlohmann::json values(const T&) {
    return nlohmann::json::object();
}

} // namespace

nlohmann::json boxValues(const model::Box& box) {
    return {{"lo", {box.lo.x, box.lo.y, box.lo.z}}, {"hi", {box.hi.x, box.hi.y, box.hi.z}}};
}

nlohmann::json actionValues(const model::Action& action) {
    return std::visit([](const auto& a) { return values(a); }, action);
}

} // namespace steerseg::workflow
