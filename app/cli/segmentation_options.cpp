#include "cli/segmentation_options.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace steerseg::cli {

namespace {

solver::Sphere parseSphere(const std::string& text, const std::string& what) {
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

void checkInside(const std::vector<solver::Sphere>& spheres, const glm::ivec3& dims,
                 const char* what) {
    for (const solver::Sphere& s : spheres) {
        try {
            solver::validateSphere(s, dims);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string(what) + ": " + e.what());
        }
    }
}

} // namespace

std::vector<std::string> segmentationValueOptions() {
    return {"seed",       "erase", "barrier",        "T",         "eps", "alpha",
            "iterations", "time",  "max-iterations", "brick-size"};
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
    r.params.T = static_cast<float>(parseNumber(args.required("T"), "--T"));
    r.params.eps = static_cast<float>(parseNumber(args.required("eps"), "--eps"));
    r.params.alpha = static_cast<float>(parseNumber(args.required("alpha"), "--alpha"));
    try {
        solver::validateParams(r.params);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    for (const std::string& s : args.values("seed")) {
        r.seeds.push_back(parseSphere(s, "--seed"));
    }
    for (const std::string& s : args.values("erase")) {
        r.erases.push_back(parseSphere(s, "--erase"));
    }
    for (const std::string& s : args.values("barrier")) {
        r.barriers.push_back(parseSphere(s, "--barrier"));
    }
    if (r.barriers.size() > solver::kMaxBarriers) {
        throw UsageError("at most " + std::to_string(solver::kMaxBarriers) + " --barrier spheres");
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

void checkSpheresInside(const SegmentationRequest& request, const glm::ivec3& dims) {
    checkInside(request.seeds, dims, "--seed");
    checkInside(request.erases, dims, "--erase");
    checkInside(request.barriers, dims, "--barrier");
}

void applySegmentation(session::Session& session, const SegmentationRequest& request) {
    for (const solver::Sphere& s : request.seeds) {
        session.addSeed(s);
    }
    for (const solver::Sphere& s : request.erases) {
        session.erase(s);
    }
    for (const solver::Sphere& s : request.barriers) {
        session.addBarrier(s);
    }
    session.setParams(request.params);
}

} // namespace steerseg::cli
