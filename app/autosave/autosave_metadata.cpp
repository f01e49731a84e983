// The autosave's metadata as JSON (autosave_snapshot.cpp frames it with the header, the CRC
// and the mask's runs): the scan, the parameters and examples, the counts, the state and the
// barriers, and the checks a decoded value must pass before a session trusts it.
#include "autosave/autosave_metadata.hpp"

#include "model/speed_kind.hpp"
#include "workflow/audit_log.hpp"
#include "workflow/param_ranges.hpp"
#include "workflow/utc_time.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::autosave {

namespace {

std::optional<model::State> stateFromName(const std::string& name) {
    for (int i = 0; i <= static_cast<int>(model::State::Error); ++i) {
        const auto s = static_cast<model::State>(i);
        if (model::stateName(s) == name) {
            return s;
        }
    }
    return std::nullopt;
}

nlohmann::json spheres(const std::vector<model::Sphere>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const model::Sphere& e : list) {
        out.push_back({e.centre.x, e.centre.y, e.centre.z, e.radius});
    }
    return out;
}

// A number the session keeps as a float: JSON may hold 1e400, which no float holds.
float readFloat(const nlohmann::json& v) {
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::abs(d) > static_cast<double>(std::numeric_limits<float>::max())) {
        throw AutosaveFormatError("a sphere or a barrier holds a number out of range");
    }
    return static_cast<float>(d);
}

// [i, j, k, radius]
model::Sphere readSphere(const nlohmann::json& e) {
    return {{readFloat(e.at(0)), readFloat(e.at(1)), readFloat(e.at(2))}, readFloat(e.at(3))};
}

std::vector<model::Sphere> readSpheres(const nlohmann::json& params, const char* key,
                                       std::size_t most = model::kMaxExamples) {
    std::vector<model::Sphere> out;
    if (!params.contains(key)) {
        return out;
    }
    for (const nlohmann::json& e : params.at(key)) {
        out.push_back(readSphere(e));
    }
    if (out.size() > most) {
        throw AutosaveFormatError(std::string("more ") + key + " examples than a session keeps");
    }
    return out;
}

// {"lo": [i, j, k], "hi": [i, j, k]} (workflow::boxValues) or absent: no box. Checked against
// the saved dims here, so a garbled box is the autosave's error, not the resumed session's.
std::optional<model::Box> readBox(const nlohmann::json& params, const glm::ivec3& dims) {
    if (!params.contains("box") || params.at("box").is_null()) {
        return std::nullopt;
    }
    const nlohmann::json& j = params.at("box");
    model::Box box;
    for (int a = 0; a < 3; ++a) {
        box.lo[a] = j.at("lo").at(a).get<int>();
        box.hi[a] = j.at("hi").at(a).get<int>();
    }
    try {
        model::validateBox(box, dims);
    } catch (const std::invalid_argument& e) {
        throw AutosaveFormatError(e.what());
    }
    return box;
}

nlohmann::json barrierList(const std::vector<model::Barrier>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const model::Barrier& b : list) {
        const model::Sphere& s = b.sphere;
        nlohmann::json e{{"sphere", {s.centre.x, s.centre.y, s.centre.z, s.radius}},
                         {"keep", b.keep}};
        if (b.tissue) {
            e["tissue"] = {{"level", b.tissue->level}, {"reach", b.tissue->reach}};
        }
        out.push_back(std::move(e));
    }
    return out;
}

// Snapshots from before the barriers were kept have none, and from before tissue levels no
// "tissue" (the engine validates the values when it holds the barriers).
std::vector<model::Barrier> readBarriers(const nlohmann::json& j) {
    std::vector<model::Barrier> out;
    if (!j.contains("barriers")) {
        return out;
    }
    for (const nlohmann::json& b : j.at("barriers")) {
        model::Barrier barrier{readSphere(b.at("sphere")), b.at("keep").get<bool>()};
        if (b.contains("tissue")) {
            const nlohmann::json& t = b.at("tissue");
            barrier.tissue = model::TissueLevel{readFloat(t.at("level")), readFloat(t.at("reach"))};
        }
        out.push_back(barrier);
    }
    if (out.size() > model::kMaxBarriers) {
        throw AutosaveFormatError("more barriers than a session holds (" +
                                  std::to_string(out.size()) + ")");
    }
    return out;
}

// Snapshots from before the speed choice have none of these keys: the threshold speed.
model::SpeedKind readSpeed(const nlohmann::json& params, const char* key) {
    if (!params.contains(key)) {
        return model::SpeedKind::Threshold;
    }
    const std::string name = params.at(key).get<std::string>();
    const std::optional<model::SpeedKind> kind = model::parseSpeedKind(name);
    if (!kind) {
        throw AutosaveFormatError("unknown speed '" + name + "'");
    }
    return *kind;
}

// A valid CRC says the bytes are the ones written, not that the writer was sane: a count no
// session can have would reach the operator's panel as is, so it is refused like a damaged file
// and the resume falls back to the autosave before it.
constexpr int kMaxSpheres = 1'000'000;

int readCount(const nlohmann::json& j, const char* key, int most) {
    const int value = j.at(key).get<int>();
    if (value < 0 || value > most) {
        throw AutosaveFormatError(std::string(key) + " is " + std::to_string(value) +
                                  ", not a count a session can have (0.." + std::to_string(most) +
                                  ")");
    }
    return value;
}

double readEvolvedTime(const nlohmann::json& j) {
    const double value = j.at("evolved_time").get<double>();
    if (!(value >= 0.0) || !std::isfinite(value)) {
        throw AutosaveFormatError("evolved_time is " + std::to_string(value) +
                                  ", not a time a session can have (0 or more)");
    }
    return value;
}

} // namespace

nlohmann::json metadata(const AutosaveSnapshot& s) {
    nlohmann::json params{
        {"preset", s.params.preset},
        {"speed", model::speedKindName(s.params.speed.kind)},
        {"speed_fallback", model::speedKindName(s.params.fallback)},
        {"inside", spheres(s.params.speed.inside)},
        {"outside", spheres(s.params.speed.outside)},
        {"painted_inside", spheres(s.params.speed.paintedInside)},
        {"painted_outside", spheres(s.params.speed.paintedOutside)},
        {"box", s.params.speed.box ? workflow::boxValues(*s.params.speed.box) : nlohmann::json()}};
    for (int i = 0; i < model::kParamCount; ++i) {
        const auto p = static_cast<model::Param>(i);
        params[std::string(model::paramName(p))] = s.params.values[workflow::indexOf(p)];
    }
    const auto saved =
        std::chrono::system_clock::time_point(std::chrono::milliseconds(s.savedAtMs));
    return {
        {"scan", {{"path", s.scan.path}, {"bytes", s.scan.bytes}, {"mtime_ns", s.scan.mtimeNs}}},
        {"dims", {s.dims.x, s.dims.y, s.dims.z}},
        {"saved_at_ms", s.savedAtMs},
        {"saved_at", workflow::isoUtc(saved)},
        {"sequence", s.sequence},
        {"state", model::stateName(s.state)},
        {"params", params},
        {"seeds", s.seeds},
        {"erasures", s.erasures},
        {"iterations", s.iterations},
        {"evolved_time", s.evolvedTime},
        {"barriers", barrierList(s.barriers)}};
}

void readMetadata(const nlohmann::json& j, AutosaveSnapshot& s) {
    const nlohmann::json& scan = j.at("scan");
    s.scan.path = scan.at("path").get<std::string>();
    s.scan.bytes = scan.at("bytes").get<std::uint64_t>();
    s.scan.mtimeNs = scan.at("mtime_ns").get<std::int64_t>();
    const nlohmann::json& dims = j.at("dims");
    s.dims = {dims.at(0).get<int>(), dims.at(1).get<int>(), dims.at(2).get<int>()};
    s.savedAtMs = j.at("saved_at_ms").get<std::int64_t>();
    s.sequence = j.at("sequence").get<std::uint64_t>();
    const auto state = stateFromName(j.at("state").get<std::string>());
    if (!state) {
        throw AutosaveFormatError("unknown workflow state '" + j.at("state").get<std::string>() +
                                  "'");
    }
    s.state = *state;
    const nlohmann::json& params = j.at("params");
    s.params.preset = params.at("preset").get<std::string>();
    s.params.speed.kind = readSpeed(params, "speed");
    s.params.fallback = readSpeed(params, "speed_fallback");
    s.params.speed.inside = readSpheres(params, "inside");
    s.params.speed.outside = readSpheres(params, "outside");
    // Snapshots from before painted strokes have none.
    s.params.speed.paintedInside =
        readSpheres(params, "painted_inside", workflow::kMaxPaintedExamples);
    s.params.speed.paintedOutside =
        readSpheres(params, "painted_outside", workflow::kMaxPaintedExamples);
    s.params.speed.box = readBox(params, s.dims); // snapshots from before the box have none
    for (int i = 0; i < model::kParamCount; ++i) {
        const auto p = static_cast<model::Param>(i);
        s.params.values[workflow::indexOf(p)] =
            params.at(std::string(model::paramName(p))).get<double>();
    }
    s.seeds = readCount(j, "seeds", kMaxSpheres);
    s.erasures = readCount(j, "erasures", kMaxSpheres);
    s.iterations = readCount(j, "iterations", std::numeric_limits<int>::max());
    s.evolvedTime = readEvolvedTime(j);
    s.barriers = readBarriers(j);
}

} // namespace steerseg::autosave
