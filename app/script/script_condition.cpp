#include "script/script_condition.hpp"

#include "model/speed_kind.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>

namespace steerseg::script {

namespace {

using Getter = std::function<double(const workflow::Status&)>;

double flag(bool b) {
    return b ? 1.0 : 0.0;
}

const std::vector<std::pair<std::string_view, Getter>>& fieldTable() {
    using S = workflow::Status;
    static const std::vector<std::pair<std::string_view, Getter>> kFields = {
        {"volume_ml", [](const S& s) { return s.volumeMl; }},
        {"iterations", [](const S& s) { return static_cast<double>(s.iterations); }},
        {"evolved_time", [](const S& s) { return s.evolvedTime; }},
        {"seeds", [](const S& s) { return static_cast<double>(s.seeds); }},
        {"erasures", [](const S& s) { return static_cast<double>(s.erasures); }},
        {"T", [](const S& s) { return static_cast<double>(s.params.T); }},
        {"eps", [](const S& s) { return static_cast<double>(s.params.eps); }},
        {"alpha", [](const S& s) { return static_cast<double>(s.params.alpha); }},
        {"radius", [](const S& s) { return s.radius; }},
        {"converged", [](const S& s) { return flag(s.converged); }},
        {"has_level_set", [](const S& s) { return flag(s.hasLevelSet); }},
        {"can_undo", [](const S& s) { return flag(s.canUndo); }},
        {"can_redo", [](const S& s) { return flag(s.canRedo); }},
        {"erase_mode", [](const S& s) { return flag(s.eraseMode); }},
        {"outside_mode", [](const S& s) { return flag(s.outsideMode); }},
        {"box_mode", [](const S& s) { return flag(s.boxMode); }},
        {"has_box", [](const S& s) { return flag(s.box.has_value()); }},
        {"inside_examples",
         [](const S& s) { return static_cast<double>(s.insideExamples.size()); }},
        {"outside_examples",
         [](const S& s) { return static_cast<double>(s.outsideExamples.size()); }},
        {"load_progress", [](const S& s) { return s.loadProgress; }},
        {"window_level", [](const S& s) { return s.view.windowLevel; }},
        {"window_width", [](const S& s) { return s.view.windowWidth; }},
        {"zoom", [](const S& s) { return s.view.zoom; }},
        {"yaw", [](const S& s) { return s.view.yawDeg; }},
        {"pitch", [](const S& s) { return s.view.pitchDeg; }},
        // The kiosk's DICOM node: series received completely, objects waiting to be sent.
        {"received",
         [](const S& s) {
             return static_cast<double>(std::count_if(s.received.begin(), s.received.end(),
                                                      [](const auto& r) { return !r.arriving; }));
         }},
        {"outbox", [](const S& s) { return static_cast<double>(s.outbox.size()); }},
        {"structures", [](const S& s) { return static_cast<double>(s.structures.size()); }},
        // The kiosk's PACS search and retrieve (Status::pacs): counters of those ended, the
        // last search's matches, a study's series, and the retrieve's images as its progress
        // bar shows them.
        {"searches", [](const S& s) { return static_cast<double>(s.pacs.searches); }},
        {"searching", [](const S& s) { return s.pacs.searching ? 1.0 : 0.0; }},
        {"found", [](const S& s) { return static_cast<double>(s.pacs.studies.size()); }},
        // A study's series (ListPacsSeries): listings ended, one under way, the last one's rows.
        {"series_listings", [](const S& s) { return static_cast<double>(s.pacs.seriesListings); }},
        {"listing_series", [](const S& s) { return s.pacs.listingSeries ? 1.0 : 0.0; }},
        {"series_found", [](const S& s) { return static_cast<double>(s.pacs.series.size()); }},
        {"retrieves", [](const S& s) { return static_cast<double>(s.pacs.retrieves); }},
        {"retrieving", [](const S& s) { return s.pacs.retrieving ? 1.0 : 0.0; }},
        {"retrieved", [](const S& s) { return static_cast<double>(s.pacs.received); }},
        {"retrieve_expected", [](const S& s) { return static_cast<double>(s.pacs.expected); }},
        {"retrieve_failed", [](const S& s) { return static_cast<double>(s.pacs.failed); }},
    };
    return kFields;
}

std::string number(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

} // namespace

const std::vector<std::string_view>& statusFields() {
    static const std::vector<std::string_view> kNames = [] {
        std::vector<std::string_view> names;
        for (const auto& [name, getter] : fieldTable()) {
            names.push_back(name);
        }
        return names;
    }();
    return kNames;
}

std::optional<double> statusField(const workflow::Status& status, std::string_view field) {
    for (const auto& [name, getter] : fieldTable()) {
        if (name == field) {
            return getter(status);
        }
    }
    return std::nullopt;
}

bool compare(double lhs, Condition::Op op, double rhs) {
    switch (op) {
    case Condition::Op::Less:
        return lhs < rhs;
    case Condition::Op::LessEqual:
        return lhs <= rhs;
    case Condition::Op::Greater:
        return lhs > rhs;
    case Condition::Op::GreaterEqual:
        return lhs >= rhs;
    case Condition::Op::Equal:
        return lhs == rhs;
    case Condition::Op::NotEqual:
        return lhs != rhs;
    }
    return false;
}

std::string_view opText(Condition::Op op) {
    switch (op) {
    case Condition::Op::Less:
        return "<";
    case Condition::Op::LessEqual:
        return "<=";
    case Condition::Op::Greater:
        return ">";
    case Condition::Op::GreaterEqual:
        return ">=";
    case Condition::Op::Equal:
        return "==";
    case Condition::Op::NotEqual:
        return "!=";
    }
    return "?";
}

bool holds(const Condition& condition, const workflow::Status& status) {
    using model::State;
    switch (condition.kind) {
    case Condition::State:
        return status.state == condition.state;
    case Condition::Loaded:
        return status.state != State::NoScan && status.state != State::Loading &&
               status.state != State::Error;
    case Condition::Converged:
        return status.converged;
    case Condition::Iterations:
        return status.iterations >= condition.count;
    case Condition::Seconds:
        return false; // the player's clock decides
    case Condition::Compare: {
        const std::optional<double> value = statusField(status, condition.field);
        return value && compare(*value, condition.op, condition.value);
    }
    case Condition::MessageHas:
        return status.message.find(condition.text) != std::string::npos;
    case Condition::ExportedHas:
        return status.exportedPath.find(condition.text) != std::string::npos;
    case Condition::Speed:
        return status.speedInForce == condition.speed;
    }
    return false;
}

std::string observed(const Condition& condition, const workflow::Status& status) {
    const std::string state = "state is " + std::string(scriptStateName(status.state));
    switch (condition.kind) {
    case Condition::State:
    case Condition::Loaded:
    case Condition::Seconds:
        return state + (status.message.empty() ? "" : " (\"" + status.message + "\")");
    case Condition::Converged:
        return std::string(status.converged ? "converged" : "not converged") + ", " + state + ", " +
               std::to_string(status.iterations) + " iterations";
    case Condition::Iterations:
        return std::to_string(status.iterations) + " iterations, " + state;
    case Condition::Compare:
        return condition.field + " is " +
               number(statusField(status, condition.field).value_or(0.0));
    case Condition::MessageHas:
        return "message is \"" + status.message + "\"";
    case Condition::ExportedHas:
        return "exported path is \"" + status.exportedPath + "\"";
    case Condition::Speed:
        return "speed is " + std::string(model::speedKindName(status.speedInForce)) +
               (status.speed != status.speedInForce
                    ? " (" + std::string(model::speedKindName(status.speed)) + " chosen)"
                    : "");
    }
    return state;
}

} // namespace steerseg::script
