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

nlohmann::json paramsJson(const workflow::ParamValues& p) {
    nlohmann::json params{
        {"preset", p.preset},
        {"speed", model::speedKindName(p.speed.kind)},
        {"speed_fallback", model::speedKindName(p.fallback)},
        {"inside", spheres(p.speed.inside)},
        {"outside", spheres(p.speed.outside)},
        {"painted_inside", spheres(p.speed.paintedInside)},
        {"painted_outside", spheres(p.speed.paintedOutside)},
        {"box", p.speed.box ? workflow::boxValues(*p.speed.box) : nlohmann::json()}};
    for (int i = 0; i < model::kParamCount; ++i) {
        const auto q = static_cast<model::Param>(i);
        params[std::string(model::paramName(q))] = p.values[workflow::indexOf(q)];
    }
    return params;
}

workflow::ParamValues readParams(const nlohmann::json& params, const glm::ivec3& dims) {
    workflow::ParamValues p;
    p.preset = params.at("preset").get<std::string>();
    p.speed.kind = readSpeed(params, "speed");
    p.fallback = readSpeed(params, "speed_fallback");
    p.speed.inside = readSpheres(params, "inside");
    p.speed.outside = readSpheres(params, "outside");
    // Snapshots from before painted strokes have none.
    p.speed.paintedInside = readSpheres(params, "painted_inside", workflow::kMaxPaintedExamples);
    p.speed.paintedOutside = readSpheres(params, "painted_outside", workflow::kMaxPaintedExamples);
    p.speed.box = readBox(params, dims); // snapshots from before the box have none
    for (int i = 0; i < model::kParamCount; ++i) {
        const auto q = static_cast<model::Param>(i);
        p.values[workflow::indexOf(q)] = params.at(std::string(model::paramName(q))).get<double>();
    }
    return p;
}

nlohmann::json codeJson(const model::StructureCode& c) {
    return {c.value, c.scheme, c.meaning};
}

model::StructureCode readCode(const nlohmann::json& j) {
    model::StructureCode c{j.at(0).get<std::string>(), j.at(1).get<std::string>(),
                           j.at(2).get<std::string>()};
    if (std::string problem = model::structureCodeProblem(c); !problem.empty()) {
        throw AutosaveFormatError("a structure's code: " + problem);
    }
    return c;
}

// Each structure's description, parameters and counts, and how many runs its mask has in the
// file (the active one's mask is the snapshot's own).
nlohmann::json structuresJson(const workflow::StructureList& list) {
    nlohmann::json items = nlohmann::json::array();
    for (std::size_t i = 0; i < list.items.size(); ++i) {
        const workflow::Structure& s = list.items[i];
        const glm::dvec3& c = s.info.colour;
        nlohmann::json item{{"name", s.info.name},
                            {"category", codeJson(s.info.category)},
                            {"type", codeJson(s.info.type)},
                            {"colour", {c.r, c.g, c.b}},
                            {"visible", s.info.visible},
                            {"seeds", s.seeds},
                            {"erasures", s.erasures},
                            {"volume_ml", s.volumeMl},
                            {"runs", i == list.active ? 0 : s.mask.runs.size()}};
        if (i != list.active) {
            item["params"] = paramsJson(s.params); // the active one's are the snapshot's
        }
        items.push_back(std::move(item));
    }
    return {{"active", list.active}, {"items", std::move(items)}};
}

// The structures without their masks' runs (structureRunCounts says how many each has).
workflow::StructureList readStructures(const nlohmann::json& j, const glm::ivec3& dims) {
    workflow::StructureList list;
    const nlohmann::json& items = j.at("items");
    if (items.empty() || items.size() > model::kMaxStructures) {
        throw AutosaveFormatError("a session holds 1 to " + std::to_string(model::kMaxStructures) +
                                  " structures, not " + std::to_string(items.size()));
    }
    list.active = j.at("active").get<std::size_t>();
    if (list.active >= items.size()) {
        throw AutosaveFormatError("the active structure is not among them");
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        const nlohmann::json& e = items[i];
        workflow::Structure s;
        s.info.name = e.at("name").get<std::string>();
        if (std::string problem = model::structureNameProblem(s.info.name); !problem.empty()) {
            throw AutosaveFormatError(problem);
        }
        s.info.category = readCode(e.at("category"));
        s.info.type = readCode(e.at("type"));
        for (int c = 0; c < 3; ++c) {
            const double v = e.at("colour").at(c).get<double>();
            if (!(v >= 0.0 && v <= 1.0)) {
                throw AutosaveFormatError("a structure's colour lies outside 0..1");
            }
            s.info.colour[c] = v;
        }
        s.info.visible = e.at("visible").get<bool>();
        s.seeds = readCount(e, "seeds", kMaxSpheres);
        s.erasures = readCount(e, "erasures", kMaxSpheres);
        s.volumeMl = e.at("volume_ml").get<double>();
        if (!(s.volumeMl >= 0.0) || !std::isfinite(s.volumeMl)) {
            throw AutosaveFormatError("a structure's volume is not a volume");
        }
        if (i != list.active) {
            s.params = readParams(e.at("params"), dims);
        }
        list.items.push_back(std::move(s));
    }
    return list;
}

} // namespace

nlohmann::json metadata(const AutosaveSnapshot& s) {
    const nlohmann::json params = paramsJson(s.params);
    const auto saved =
        std::chrono::system_clock::time_point(std::chrono::milliseconds(s.savedAtMs));
    std::size_t structureRuns = 0;
    if (s.structures) {
        for (std::size_t i = 0; i < s.structures->items.size(); ++i) {
            structureRuns +=
                i == s.structures->active ? 0 : s.structures->items[i].mask.runs.size();
        }
    }
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
        {"barriers", barrierList(s.barriers)},
        {"structures", s.structures ? structuresJson(*s.structures) : nlohmann::json()},
        {"structure_runs", structureRuns}};
}

std::vector<std::uint64_t> structureRunCounts(const nlohmann::json& j) {
    std::vector<std::uint64_t> out;
    if (!j.contains("structures") || j.at("structures").is_null()) {
        return out;
    }
    for (const nlohmann::json& e : j.at("structures").at("items")) {
        out.push_back(e.at("runs").get<std::uint64_t>());
    }
    return out;
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
    s.params = readParams(j.at("params"), s.dims);
    s.seeds = readCount(j, "seeds", kMaxSpheres);
    s.erasures = readCount(j, "erasures", kMaxSpheres);
    s.iterations = readCount(j, "iterations", std::numeric_limits<int>::max());
    s.evolvedTime = readEvolvedTime(j);
    s.barriers = readBarriers(j);
    if (j.contains("structures") && !j.at("structures").is_null()) {
        s.structures = readStructures(j.at("structures"), s.dims);
    }
}

} // namespace steerseg::autosave
