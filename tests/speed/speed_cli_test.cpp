// `steerseg segment --speed ...` end to end: usage errors for the speed options, the edge speed
// with --probe on the built-in sample and the report's speed fields.
#include "exports/image_file.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>

namespace steerseg::test {
namespace {

const std::string kBase = "segment --input builtin:sample --output /nonexistent/never.nii.gz "
                          "--seed 80,56,52,5 --alpha 0.8 --iterations 5 ";

void expectUsageError(const std::string& options, const std::string& message) {
    SCOPED_TRACE(options);
    const CliRun r = runSteerseg(kBase + options);
    EXPECT_EQ(r.exitCode, 2) << r.out << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(SpeedCli, BadSpeedOptionsAreUsageErrors) {
    const std::string te = "--T 800 --eps 100 ";
    expectUsageError(te + "--speed fast", "--speed must be threshold, edge or classify");
    expectUsageError(te + "--speed edge", "--speed edge needs --kappa v or --probe");
    expectUsageError(te + "--speed edge --kappa -2", "--kappa must be a number > 0");
    expectUsageError(te + "--kappa 5", "--kappa goes with --speed edge");
    expectUsageError(te + "--smooth 5", "--smooth needs --conductance v or --probe");
    expectUsageError(te + "--speed classify --inside 80,56,52,4",
                     "--speed classify needs an outside example");
    expectUsageError(te + "--speed edge --inside 80,56,52,4 --kappa 5",
                     "--inside and --outside go with --speed classify");
    expectUsageError(te + "--speed classify --probe 80,56,52,4 --outside 900,1,1,3", "--outside");
    expectUsageError("--speed edge --probe 900,56,52,4", "--probe");
    // Without --probe, T and eps are still required.
    expectUsageError("--speed edge --kappa 5", "--T");
}

TEST(SpeedCli, EdgeSpeedWithProbeOnTheSampleLesion) {
    const auto dir = tempDir("speed_cli");
    const auto report = dir / "report.json";
    const CliRun r =
        runSteerseg("segment --input builtin:sample --seed 80,56,52,5 --probe 80,56,52,4 "
                    "--speed edge --smooth 5 --alpha 0.8 --converge --output " +
                    (dir / "lesion.nii.gz").string() + " --report " + report.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(report);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j.at("speed").at("name"), "edge");
    EXPECT_EQ(j.at("speed").at("smoothing_iterations"), 5);
    EXPECT_GT(j.at("speed").at("conductance").get<double>(), 0.0);
    EXPECT_GT(j.at("speed").at("kappa").get<double>(), 0.0);
    EXPECT_GT(j.at("preprocessing_seconds").get<double>(), 0.0);
    EXPECT_EQ(j.at("training_seconds").get<double>(), 0.0);
    EXPECT_EQ(j.at("stop_reason"), "converged");
    // The probe's T is the lesion's mean (800 in the phantom), eps at least the floor.
    EXPECT_NEAR(j.at("T").get<double>(), 800.0, 20.0);
    EXPECT_GE(j.at("eps").get<double>(), 10.0);
    // The lesion is a 7.24 ml ball; the threshold speed finds 7.12 ml.
    EXPECT_NEAR(j.at("volume_ml").get<double>(), 7.24, 1.0);
}

TEST(SpeedCli, ExplicitValuesOverrideTheProbeAndThresholdIsTheDefault) {
    const CliRun probed = runSteerseg(
        "segment --input builtin:sample --seed 80,56,52,5 --probe 80,56,52,4 --T 790 --eps 60 "
        "--speed edge --kappa 7 --alpha 0.8 --iterations 2 --output " +
        (tempDir("speed_cli_override") / "m.nii.gz").string());
    ASSERT_EQ(probed.exitCode, 0) << probed.err;
    const nlohmann::json j = nlohmann::json::parse(probed.out);
    EXPECT_EQ(j.at("T").get<double>(), 790.0);
    EXPECT_EQ(j.at("eps").get<double>(), 60.0);
    EXPECT_EQ(j.at("speed").at("kappa").get<double>(), 7.0);
    EXPECT_EQ(j.at("speed").at("smoothing_iterations"), 0);

    const CliRun plain = runSteerseg("segment --input builtin:sample --seed 80,56,52,5 --T 800 "
                                     "--eps 100 --alpha 0.8 --iterations 2 --output " +
                                     (tempDir("speed_cli_plain") / "m.nii.gz").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    const nlohmann::json p = nlohmann::json::parse(plain.out);
    EXPECT_EQ(p.at("speed").at("name"), "threshold");
    EXPECT_FALSE(p.at("speed").contains("kappa"));
}

// render's speed-function view was --speed before segment took the name.
TEST(SpeedCli, RenderTakesTheSpeedViewAsSpeedView) {
    const auto out = tempDir("speed_cli_render") / "speed.png";
    const CliRun r =
        runSteerseg("render --input builtin:sample --view sagittal --speed-view --T 800 "
                    "--eps 60 --size 64x64 --output " +
                    out.string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(out));
    const CliRun noEps = runSteerseg("render --input builtin:sample --view sagittal --speed-view "
                                     "--output " +
                                     out.string());
    EXPECT_EQ(noEps.exitCode, 2);
    EXPECT_NE(noEps.err.find("--speed-view needs --T and a positive --eps"), std::string::npos)
        << noEps.err;
    // With a segmentation the view shows its speed: classify's needs no --T or --eps, and the
    // whole slice is evaluated, not only where the front went.
    const auto classify = out.parent_path() / "classify.png";
    const CliRun c = runSteerseg(
        "render --input builtin:sample --view axial --speed-view --size 64x64 --seed 80,56,52,4 "
        "--speed classify --probe 80,56,52,4 --outside 30,30,52,4 --alpha 0.5 --iterations 1 "
        "--output " +
        classify.string());
    ASSERT_EQ(c.exitCode, 0) << c.err;
    const RgbaImage picture = exports::readImage(classify);
    int green = 0;
    int blue = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const std::uint8_t* px = picture.at(x, y);
            // Saturated: the scan's own grey, tinted, lies within a few levels of neutral.
            green += px[1] > px[2] + 60 ? 1 : 0;
            blue += px[2] > px[1] + 60 ? 1 : 0;
        }
    }
    EXPECT_GT(green, 0);
    EXPECT_GT(blue, picture.width * picture.height / 4); // the background, far from any front
}

} // namespace
} // namespace steerseg::test
