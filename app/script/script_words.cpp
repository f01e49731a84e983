#include "script/script_words.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace steerseg::script {

namespace {

constexpr std::array<std::string_view, 10> kStateNames = {
    "no_scan", "loading", "inspect",   "seeding", "evolving",
    "paused",  "review",  "exporting", "done",    "error"};

} // namespace

std::string_view scriptStateName(model::State state) {
    const auto n = static_cast<std::size_t>(state);
    return n < kStateNames.size() ? kStateNames[n] : std::string_view("unknown");
}

std::optional<model::State> scriptStateFromName(std::string_view name) {
    for (std::size_t n = 0; n < kStateNames.size(); ++n) {
        if (kStateNames[n] == name) {
            return static_cast<model::State>(n);
        }
    }
    return std::nullopt;
}

namespace detail {

using Op = Condition::Op;

bool isKeyName(std::string_view key) {
    static const std::vector<std::string_view> kNamed = {
        "space", "enter",  "escape",   "backspace", "tab",   "left",   "right", "up",
        "down",  "pageup", "pagedown", "plus",      "minus", "delete", "home",  "end"};
    if (key.size() == 1) {
        return (key[0] >= 'a' && key[0] <= 'z') || (key[0] >= '0' && key[0] <= '9');
    }
    if (key.size() >= 2 && key.size() <= 3 && key[0] == 'f') {
        const std::string digits(key.substr(1));
        if (digits.find_first_not_of("0123456789") == std::string::npos && digits[0] != '0') {
            const int n = std::stoi(digits);
            return n >= 1 && n <= 12;
        }
        return false;
    }
    return std::find(kNamed.begin(), kNamed.end(), key) != kNamed.end();
}

model::State stateWord(Words& words) {
    const std::string name = words.text("a state");
    if (const auto state = scriptStateFromName(name)) {
        return *state;
    }
    std::string known;
    for (const std::string_view s : kStateNames) {
        known += (known.empty() ? "" : ", ") + std::string(s);
    }
    throw LineError("unknown state '" + name + "' (states: " + known + ")");
}

model::Param paramWord(Words& words) {
    const std::string name = words.text("a parameter (T, eps, alpha, radius)");
    static const std::map<std::string, model::Param, std::less<>> kParams = {
        {"T", model::Param::T},
        {"eps", model::Param::Eps},
        {"alpha", model::Param::Alpha},
        {"radius", model::Param::Radius}};
    const auto it = kParams.find(name);
    if (it == kParams.end()) {
        throw LineError("unknown parameter '" + name + "' (T, eps, alpha, radius)");
    }
    return it->second;
}

model::SliceAxis axisWord(Words& words) {
    const std::string name = words.text("a slice axis (axial, coronal, sagittal)");
    if (name == "axial") {
        return model::SliceAxis::Axial;
    }
    if (name == "coronal") {
        return model::SliceAxis::Coronal;
    }
    if (name == "sagittal") {
        return model::SliceAxis::Sagittal;
    }
    throw LineError("unknown slice axis '" + name + "' (axial, coronal, sagittal)");
}

Op opWord(Words& words) {
    const std::string op = words.text("a comparison (<, <=, >, >=, ==, !=)");
    static const std::map<std::string, Op, std::less<>> kOps = {
        {"<", Op::Less},          {"<=", Op::LessEqual}, {">", Op::Greater},
        {">=", Op::GreaterEqual}, {"==", Op::Equal},     {"!=", Op::NotEqual}};
    const auto it = kOps.find(op);
    if (it == kOps.end()) {
        throw LineError("'" + op + "' is not a comparison (<, <=, >, >=, ==, !=)");
    }
    return it->second;
}

std::string pathWord(Words& words, const char* what) {
    std::string path = words.text(what);
    if (path.empty()) {
        throw LineError(std::string(what) + " is empty");
    }
    detail::checkVariables(path);
    return path;
}

glm::dvec3 voxelWords(Words& words) {
    const double i = words.number("the voxel's i", -kMaxCoordinate, kMaxCoordinate);
    const double j = words.number("the voxel's j", -kMaxCoordinate, kMaxCoordinate);
    const double k = words.number("the voxel's k", -kMaxCoordinate, kMaxCoordinate);
    return {i, j, k};
}

double timeoutWords(Words& w) {
    if (w.accept("timeout")) {
        return w.number("the timeout (seconds)", 0.0, kMaxSeconds);
    }
    return kDefaultWaitTimeout;
}

} // namespace detail

} // namespace steerseg::script
