// The panel's words for states, parameters, speeds and scans (declared in panel_model.hpp).
#include "ui/panel_model.hpp"

#include <filesystem>

namespace steerseg::ui {

using model::Param;
using model::State;

std::string stateLabel(State s) {
    switch (s) {
    case State::NoScan:
        return "No scan";
    case State::Loading:
        return "Loading";
    case State::Inspect:
        return "Inspect";
    case State::Seeding:
        return "Seeding";
    case State::Evolving:
        return "Evolving";
    case State::Paused:
        return "Paused";
    case State::Review:
        return "Review";
    case State::Exporting:
        return "Exporting";
    case State::Done:
        return "Done";
    case State::Error:
        return "Error";
    }
    return "?";
}

std::string paramLabel(Param p) {
    switch (p) {
    case Param::T:
        return "T";
    case Param::Eps:
        return "eps";
    case Param::Alpha:
        return "alpha";
    case Param::Radius:
        return "brush";
    }
    return "?";
}

std::string speedLabel(model::SpeedKind kind) {
    switch (kind) {
    case model::SpeedKind::Threshold:
        return "Threshold";
    case model::SpeedKind::Edge:
        return "Edge";
    case model::SpeedKind::Classify:
        return "Classify";
    }
    return "?";
}

std::string proceedLabel(State s) {
    switch (s) {
    case State::Inspect:
        return "Seed";
    case State::Seeding:
        return "Run";
    case State::Evolving:
    case State::Paused:
        return "Review";
    case State::Review:
        return "Export";
    default:
        return {};
    }
}

std::string scanLabel(const std::string& path) {
    if (path == "builtin:sample") {
        return "Sample";
    }
    std::filesystem::path p(path);
    if (!p.has_filename()) {
        p = p.parent_path(); // a folder given with its trailing slash
    }
    const std::string name = p.filename().string();
    return name.empty() ? path : name;
}

} // namespace steerseg::ui
