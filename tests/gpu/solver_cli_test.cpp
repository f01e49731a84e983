// `steerseg segment` end to end: bad parameters give exit status 2 and a clear message; a run on
// the built-in sample writes a mask and a report with the documented fields.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

namespace steerseg::test {
namespace {

struct RunResult {
    int status = -1;
    std::string output;
};

RunResult runSegment(const std::string& arguments) {
    const CliRun run = runSteerseg("segment " + arguments);
    return {run.exitCode, run.out + run.err};
}

const std::string kBase = "--input builtin:sample --output /nonexistent/never.nii.gz ";

TEST(SolverCli, BadParametersAreUsageErrors) {
    const RunResult eps =
        runSegment(kBase + "--seed 80,56,52,5 --T 800 --eps -1 --alpha 0.5 --iterations 5");
    EXPECT_EQ(eps.status, 2) << eps.output;
    EXPECT_NE(eps.output.find("eps must be >= 0"), std::string::npos) << eps.output;

    const RunResult alpha =
        runSegment(kBase + "--seed 80,56,52,5 --T 800 --eps 50 --alpha 1.5 --iterations 5");
    EXPECT_EQ(alpha.status, 2) << alpha.output;
    EXPECT_NE(alpha.output.find("alpha must be in [0, 1]"), std::string::npos) << alpha.output;

    const RunResult noSeed = runSegment(kBase + "--T 800 --eps 50 --alpha 0.5 --iterations 5");
    EXPECT_EQ(noSeed.status, 2) << noSeed.output;
    EXPECT_NE(noSeed.output.find("at least one --seed"), std::string::npos) << noSeed.output;

    const RunResult outside =
        runSegment(kBase + "--seed 500,56,52,5 --T 800 --eps 50 --alpha 0.5 --iterations 5");
    EXPECT_EQ(outside.status, 2) << outside.output;
    EXPECT_NE(outside.output.find("outside the volume"), std::string::npos) << outside.output;

    const RunResult modes = runSegment(
        kBase + "--seed 80,56,52,5 --T 800 --eps 50 --alpha 0.5 --iterations 5 --converge");
    EXPECT_EQ(modes.status, 2) << modes.output;
    EXPECT_NE(modes.output.find("exactly one of"), std::string::npos) << modes.output;
}

TEST(SolverCli, SegmentsTheSampleLesionAndWritesMaskAndReport) {
    const auto dir = tempDir("solver_cli");
    const auto mask = dir / "lesion.nii.gz";
    const auto report = dir / "report.json";
    const RunResult r = runSegment("--input builtin:sample --seed 80,56,52,5 --T 800 --eps 100 "
                                   "--alpha 0.8 --time 0.1 --output " +
                                   mask.string() + " --report " + report.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(mask));
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const char* key :
         {"iterations", "evolved_time", "solve_seconds", "iterations_per_second", "converged",
          "inside_voxels", "volume_ml", "peak_active_bricks", "total_bricks", "peak_pool_bytes",
          "dense_phi_bytes", "active_bricks", "pool_bytes", "renderer", "stop_reason"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_NEAR(j["evolved_time"].get<double>(), 0.1, 1e-5);
    EXPECT_EQ(j["stop_reason"], "time_reached");
    EXPECT_GT(j["inside_voxels"].get<double>(), 4.0 / 3.0 * 3.14159 * 125.0); // grew from r = 5
    EXPECT_LT(j["peak_active_bricks"].get<double>(), j["total_bricks"].get<double>());
    EXPECT_LE(j["active_bricks"].get<double>(), j["peak_active_bricks"].get<double>());
    EXPECT_LE(j["pool_bytes"].get<double>(), j["peak_pool_bytes"].get<double>());
}

} // namespace
} // namespace steerseg::test
