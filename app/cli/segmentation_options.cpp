#include "cli/segmentation_options.hpp"

#include "session/speed_probe.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace steerseg::cli {

namespace {

model::Sphere parseSphere(const std::string& text, const std::string& what) {
    const std::vector<double> v = parseNumberList(text, 4, what);
    // Spheres are float; a double past float's range would not convert (undefined behaviour).
    // What fits the scan is checked once it is read (checkSpheresInside).
    for (const double x : v) {
        if (std::abs(x) > static_cast<double>(std::numeric_limits<float>::max())) {
            throw UsageError(what + ": " + text + " holds a number out of range");
        }
    }
    return {glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])),
            static_cast<float>(v[3])};
}

session::RunMode parseRunMode(const Args& args) {
    const auto iterations = args.integer("iterations");
    const auto time = args.number("time");
    const bool converge = args.flag("converge");
    if (static_cast<int>(iterations.has_value()) + static_cast<int>(time.has_value()) +
            static_cast<int>(converge) !=
        1) {
        throw UsageError("give exactly one of --iterations N, --time t, --converge");
    }
    const auto maxIterations = args.integer("max-iterations");
    if (maxIterations && iterations) {
        throw UsageError("--max-iterations goes with --time or --converge");
    }
    session::RunMode mode;
    const long long count = maxIterations.value_or(iterations.value_or(100000));
    if (count < 1 || count > 100000000) {
        throw UsageError("iteration counts must be between 1 and 100000000");
    }
    mode.iterations = static_cast<int>(count);
    if (time) {
        if (*time < 0.0 || *time > 1e7) {
            throw UsageError("--time must be between 0 and 1e7");
        }
        mode.kind = session::RunMode::Time;
        mode.time = static_cast<float>(*time);
    } else if (converge) {
        mode.kind = session::RunMode::Converge;
    }
    return mode;
}

void checkInside(const std::vector<model::Sphere>& spheres, const glm::ivec3& dims,
                 const char* what) {
    for (const model::Sphere& s : spheres) {
        try {
            model::validateSphere(s, dims);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string(what) + ": " + e.what());
        }
    }
}

float positiveOption(const Args& args, const char* name) {
    const double v = *args.number(name);
    if (!(v > 0.0) || v > static_cast<double>(std::numeric_limits<float>::max())) {
        throw UsageError(std::string("--") + name + " must be a number > 0");
    }
    return static_cast<float>(v);
}

// --speed and what each speed takes; what needs the scan (the probe) is left to
// completeWithScan.
void parseSpeed(const Args& args, SegmentationRequest& r) {
    const std::string name = args.value("speed").value_or("threshold");
    const auto kind = model::parseSpeedKind(name);
    if (!kind) {
        throw UsageError("--speed must be threshold, edge or classify (got '" + name + "')");
    }
    r.speed.kind = *kind;
    const long long smooth = args.integer("smooth").value_or(0);
    if (smooth < 0 || smooth > speed::kMaxSmoothingIterations) {
        throw UsageError("--smooth must be between 0 and " +
                         std::to_string(speed::kMaxSmoothingIterations));
    }
    r.speed.smoothing.iterations = static_cast<int>(smooth);
    if (args.value("conductance")) {
        r.speed.smoothing.conductance = positiveOption(args, "conductance");
        r.explicitConductance = true;
    }
    if (args.value("kappa")) {
        if (*kind != model::SpeedKind::Edge) {
            throw UsageError("--kappa goes with --speed edge");
        }
        r.speed.kappa = positiveOption(args, "kappa");
        r.explicitKappa = true;
    }
    for (const std::string& s : args.values("inside")) {
        r.speed.inside.push_back(parseSphere(s, "--inside"));
    }
    for (const std::string& s : args.values("outside")) {
        r.speed.outside.push_back(parseSphere(s, "--outside"));
    }
    if (*kind != model::SpeedKind::Classify &&
        (!r.speed.inside.empty() || !r.speed.outside.empty())) {
        throw UsageError("--inside and --outside go with --speed classify");
    }
    if (const auto probe = args.value("probe")) {
        r.probe = parseSphere(*probe, "--probe");
    }
    const bool probe = r.probe.has_value();
    if (smooth > 0 && !r.explicitConductance && !probe) {
        throw UsageError("--smooth needs --conductance v or --probe i,j,k,r");
    }
    if (*kind == model::SpeedKind::Edge && !r.explicitKappa && !probe) {
        throw UsageError("--speed edge needs --kappa v or --probe i,j,k,r");
    }
    // Its inside examples need no option: every seed is one (completeWithScan).
    if (*kind == model::SpeedKind::Classify && r.speed.outside.empty()) {
        throw UsageError("--speed classify needs an outside example (--outside i,j,k,r); the "
                         "seeds, --probe and --inside are the inside examples");
    }
}

void validateRequest(const SegmentationRequest& r, const glm::ivec3* dims) {
    try {
        model::validateParams(r.params);
        if (dims != nullptr) {
            session::validateSpeedSettings(r.speed, *dims);
        }
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

} // namespace

std::vector<std::string> segmentationValueOptions() {
    return {"seed",        "erase", "barrier",        "T",          "eps",   "alpha",
            "iterations",  "time",  "max-iterations", "brick-size", "speed", "smooth",
            "conductance", "kappa", "inside",         "outside",    "probe"};
}

std::vector<std::string> segmentationFlagOptions() {
    return {"converge", "dense", "stop-on-leak"};
}

bool wantsSegmentation(const Args& args) {
    return !args.values("seed").empty() || args.value("iterations") || args.value("time") ||
           args.flag("converge") || args.value("alpha");
}

SegmentationRequest parseSegmentation(const Args& args) {
    SegmentationRequest r;
    parseSpeed(args, r);
    // --probe suggests T and eps; without it they are required.
    const bool probe = r.probe.has_value();
    const auto number = [&](const char* name) {
        return static_cast<float>(
            parseNumber(probe ? args.value(name).value_or("0") : args.required(name),
                        std::string("--") + name));
    };
    r.explicitT = args.value("T").has_value();
    r.explicitEps = args.value("eps").has_value();
    r.params.T = number("T");
    r.params.eps = number("eps");
    r.params.alpha = static_cast<float>(parseNumber(args.required("alpha"), "--alpha"));
    validateRequest(r, nullptr);
    for (const std::string& s : args.values("seed")) {
        r.seeds.push_back(parseSphere(s, "--seed"));
    }
    for (const std::string& s : args.values("erase")) {
        r.erases.push_back(parseSphere(s, "--erase"));
    }
    for (const std::string& s : args.values("barrier")) {
        r.barriers.push_back(parseSphere(s, "--barrier"));
    }
    if (r.barriers.size() > model::kMaxBarriers) {
        throw UsageError("at most " + std::to_string(model::kMaxBarriers) + " --barrier spheres");
    }
    if (r.seeds.empty()) {
        throw UsageError("give at least one --seed i,j,k,r");
    }
    r.mode = parseRunMode(args);
    r.options.dense = args.flag("dense");
    r.options.stopOnLeak = args.flag("stop-on-leak");
    const long long brick = args.integer("brick-size").value_or(0);
    if (brick != 0 && brick != 4 && brick != 8 && brick != 16) {
        throw UsageError("--brick-size must be 4, 8 or 16");
    }
    r.options.brickSize = static_cast<int>(brick);
    return r;
}

void completeWithScan(SegmentationRequest& request, const Volume& scan) {
    const glm::ivec3 dims = scan.dims();
    checkInside(request.seeds, dims, "--seed");
    checkInside(request.erases, dims, "--erase");
    checkInside(request.barriers, dims, "--barrier");
    checkInside(request.speed.inside, dims, "--inside");
    checkInside(request.speed.outside, dims, "--outside");
    if (request.probe) {
        checkInside({*request.probe}, dims, "--probe");
        session::SpeedProbe p;
        try {
            p = session::probeSpeed(scan, *request.probe);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--probe: ") + e.what());
        }
        // Explicit values override what the probe suggests.
        if (!request.explicitT) {
            request.params.T = static_cast<float>(p.T);
        }
        if (!request.explicitEps) {
            request.params.eps = static_cast<float>(p.eps);
        }
        if (!request.explicitConductance) {
            request.speed.smoothing.conductance = static_cast<float>(p.conductance);
        }
        if (request.speed.kind == model::SpeedKind::Edge && !request.explicitKappa) {
            request.speed.kappa = static_cast<float>(p.kappa);
        }
        if (request.speed.kind == model::SpeedKind::Classify) {
            request.speed.inside.push_back(*request.probe);
        }
    }
    if (request.speed.kind == model::SpeedKind::Classify) {
        // An operator's seeds lie in the structure, often in parts the probe does not reach:
        // inside examples too (docs/speed.md, "Accuracy": the liver's Dice 0.72 -> 0.80).
        request.speed.inside.insert(request.speed.inside.end(), request.seeds.begin(),
                                    request.seeds.end());
    }
    validateRequest(request, &dims);
}

void applySegmentation(session::Session& session, const SegmentationRequest& request) {
    for (const model::Sphere& s : request.seeds) {
        session.addSeed(s);
    }
    for (const model::Sphere& s : request.erases) {
        session.erase(s);
    }
    for (const model::Sphere& s : request.barriers) {
        session.addBarrier({s, false});
    }
    session.setParams(request.params);
    session.setSpeed(request.speed);
}

} // namespace steerseg::cli
