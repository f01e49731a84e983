// steerseg-itk-levelset: the reference for `steerseg segment`. Same command line and report
// fields, solved by ITK's sparse-field ThresholdSegmentationLevelSetImageFilter on the CPU.
#include "cli/args.hpp"
#include "itk_image_io.hpp"
#include "seed_level_set.hpp"
#include "threshold_level_set.hpp"

#include <cstdio>
#include <exception>
#include <fstream>
#include <itkConfigure.h>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace {

using namespace steerseg;
using namespace steerseg::itkbench;

constexpr const char* kUsage =
    "steerseg-itk-levelset --input PATH --seed i,j,k,r [--seed ...] --T v --eps v --alpha a\n"
    "    (--iterations N | --time t [--max-iterations N] | --converge [--max-iterations N]\n"
    "    [--rms v]) [--interpolate-surface] [--spheres mm|voxels] --output MASK.nii.gz\n"
    "    [--report REPORT.json]";

constexpr long long kDefaultConvergeCap = 20000;

LevelSetParams parseParams(const cli::Args& args) {
    LevelSetParams p;
    p.target = cli::parseNumber(args.required("T"), "--T");
    p.epsilon = cli::parseNumber(args.required("eps"), "--eps");
    p.alpha = cli::parseNumber(args.required("alpha"), "--alpha");
    const bool byIterations = args.value("iterations").has_value();
    const bool byTime = args.value("time").has_value();
    const bool byConvergence = args.flag("converge");
    if (static_cast<int>(byIterations) + static_cast<int>(byTime) +
            static_cast<int>(byConvergence) !=
        1) {
        throw cli::UsageError("give exactly one of --iterations, --time, --converge");
    }
    const std::optional<long long> cap = args.integer("max-iterations");
    if (byIterations) {
        p.stop = StopRule::Iterations;
        p.iterations = *args.integer("iterations");
    } else if (byTime) {
        p.stop = StopRule::Time;
        p.time = *args.number("time");
        p.iterations = cap.value_or(0);
    } else {
        p.stop = StopRule::Converge;
        p.iterations = cap.value_or(kDefaultConvergeCap);
        p.maxRmsChange = args.number("rms").value_or(p.maxRmsChange);
    }
    if (cap && *cap < 1) {
        throw cli::UsageError("--max-iterations must be >= 1");
    }
    p.interpolateSurface = args.flag("interpolate-surface");
    // mm (the default): the seeds are the product's spheres, as `steerseg segment` draws them.
    const std::string spheres = args.value("spheres").value_or("mm");
    if (spheres != "mm" && spheres != "voxels") {
        throw cli::UsageError("--spheres is mm or voxels, not '" + spheres + "'");
    }
    p.spheres = spheres == "mm" ? SeedSpheres::Millimetres : SeedSpheres::Voxels;
    return p;
}

int run(const std::vector<std::string>& words) {
    const cli::Args args(words,
                         {"input", "seed", "T", "eps", "alpha", "iterations", "time",
                          "max-iterations", "rms", "spheres", "output", "report"},
                         {"converge", "interpolate-surface"});
    if (!args.positional().empty()) {
        throw cli::UsageError("unexpected argument '" + args.positional().front() + "'");
    }
    const std::string input = args.required("input");
    const std::string output = args.required("output");
    std::vector<Seed> seeds;
    for (const std::string& s : args.values("seed")) {
        seeds.push_back(parseSeed(s));
    }
    if (seeds.empty()) {
        throw cli::UsageError("at least one --seed i,j,k,r is needed");
    }
    const LevelSetParams params = parseParams(args);

    const FloatImage::Pointer scan = readFloatImage(input);
    const LevelSetResult r = runThresholdLevelSet(scan, seeds, params);
    writeMask(output, r.mask);

    const auto spacing = scan->GetSpacing();
    nlohmann::ordered_json j;
    j["solver"] = "itk-sparse-field";
    j["itk_version"] = ITK_VERSION_STRING;
    j["iterations"] = r.iterations;
    j["evolved_time"] = r.evolvedTime;
    j["solve_seconds"] = r.solveSeconds;
    j["cpu_seconds"] = r.cpuSeconds;
    j["iterations_per_second"] =
        r.solveSeconds > 0.0 ? static_cast<double>(r.iterations) / r.solveSeconds : 0.0;
    j["converged"] = r.converged;
    j["rms_change"] = r.rmsChange;
    j["inside_voxels"] = r.insideVoxels;
    j["volume_ml"] =
        static_cast<double>(r.insideVoxels) * spacing[0] * spacing[1] * spacing[2] / 1000.0;
    j["threads"] = r.threads;
    j["interpolate_surface"] = params.interpolateSurface;
    j["spheres"] = params.spheres == SeedSpheres::Millimetres ? "mm" : "voxels";
    const std::string text = j.dump(2);
    std::printf("%s\n", text.c_str());
    if (const auto reportPath = args.value("report")) {
        std::ofstream out(*reportPath);
        out << text << "\n";
        if (!out) {
            throw std::runtime_error(*reportPath + ": cannot write the report");
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const steerseg::cli::UsageError& e) {
        std::fprintf(stderr, "steerseg-itk-levelset: %s\nusage: %s\n", e.what(), kUsage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "steerseg-itk-levelset: %s\n", e.what());
        return 1;
    }
}
