// `segment --click` and `--box`: prompts replayed through the kiosk's workflow, and their
// refusals.
#include "model/box.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace steerseg::test {
namespace {

std::string out(const char* name) {
    return (std::filesystem::path(testing::TempDir()) / name).string();
}

TEST(SegmentClicks, BadClicksAndTheOptionsTheyReplaceAreRefused) {
    struct Case {
        const char* args;
        const char* says;
    };
    for (const Case& c : {
             Case{"--click 1,2,3", "expected 4 or 5 fields"},
             Case{"--click 1,2,3,*", "must be + or -"},
             Case{"--click 1,2,x,+", "--click's voxel index"},
             Case{"--click 80,56,52,+,0", "radius must be > 0"},
             Case{"--click 80,56,52,+,1e9", "lies outside the brush's range [1, 48]"},
             Case{"--click 80,56,52,-", "first --click must be positive"},
             Case{"--click 80,56,52,+ --seed 80,56,52,3", "--seed does not go with --click"},
             Case{"--click 80,56,52,+ --converge", "--converge does not go with --click"},
             Case{"--click 80,56,52,+ --max-iterations 0", "--max-iterations must be >= 1"},
         }) {
        const CliRun r = runSteerseg(std::string("segment --input builtin:sample --output ") +
                                     out("clicks.nii.gz") + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    }
    const CliRun far = runSteerseg("segment --input builtin:sample --output " +
                                   out("clicks.nii.gz") + " --click 500,56,52,+");
    EXPECT_NE(far.exitCode, 0);
    EXPECT_NE(far.err.find("outside the scan"), std::string::npos) << far.err;
}

TEST(SegmentClicks, EachClickRunsFromTheSurfaceAndIsReported) {
    const std::string mask = out("clicks.nii.gz");
    const CliRun r = runSteerseg("segment --input builtin:sample --output " + mask +
                                 " --click 80,56,52,+,3 --click 80,56,58,-,2 --max-iterations 40");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out);
    ASSERT_EQ(report["clicks"].size(), 2U);
    EXPECT_EQ(report["clicks"][0]["kind"], "initial");
    EXPECT_EQ(report["clicks"][1]["kind"], "negative");
    EXPECT_EQ(report["clicks"][0]["barriers"], 1) << "the first click's sphere keeps";
    EXPECT_EQ(report["clicks"][1]["barriers"], 2);
    EXPECT_LE(report["clicks"][0]["iterations"].get<int>(), 40);
    EXPECT_GT(report["clicks"][1]["iterations"].get<int>(),
              report["clicks"][0]["iterations"].get<int>())
        << "the second click's run goes on from the first's";
    EXPECT_TRUE(std::filesystem::exists(mask));
}

// An empty, inverted or out-of-scan box, and a box with what it replaces: exit 2, named.
TEST(SegmentClicks, BadBoxesAreRefused) {
    struct Case {
        const char* args;
        const char* says;
    };
    for (const Case& c : {
             Case{"--box ''", "expected 6 fields, got 1"},
             Case{"--box 1,2,3,4,5", "expected 6 fields, got 5"},
             Case{"--box 60,40,40,50,72,64", "inverted on axis i"},
             Case{"--box 60,40,-1,100,72,64", "voxel indices start at 0"},
             Case{"--box 60,40,40,100,72,x", "--box's voxel index"},
             Case{"--box 60,40,40,100,72,96", "reaches outside the scan"},
             Case{"--box 60,40,40,100,72,64 --seed 80,56,52,3", "--seed does not go with"},
         }) {
        const CliRun r = runSteerseg(std::string("segment --input builtin:sample --output ") +
                                     out("box.nii.gz") + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    }
}

// The box alone: its probe and seed at the centre, then its run, which never leaves it; a
// negative click after it corrects as any other.
TEST(SegmentClicks, TheBoxRunsFromItsCentreAndTheSurfaceStaysInIt) {
    const std::string mask = out("box.nii.gz");
    const model::Box box{{60, 40, 40}, {100, 72, 64}};
    const CliRun r = runSteerseg("segment --input builtin:sample --output " + mask +
                                 " --box 60,40,40,100,72,64 --click 80,56,58,-,2 "
                                 "--max-iterations 120");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto report = nlohmann::json::parse(r.out);
    ASSERT_EQ(report["clicks"].size(), 2U);
    EXPECT_EQ(report["clicks"][0]["kind"], "box");
    EXPECT_EQ(report["clicks"][1]["kind"], "negative");
    EXPECT_GT(report["clicks"][0]["iterations"].get<int>(), 0);
    const Volume result = scan::readScan(mask).volume;
    std::size_t inside = 0;
    std::size_t beyond = 0;
    const glm::ivec3 d = result.dims();
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                if (result.valueAt(i, j, k) > 0.5) {
                    ++inside;
                    beyond += model::contains(box, {i, j, k}) ? 0 : 1;
                }
            }
        }
    }
    EXPECT_GT(inside, 1000U);
    EXPECT_EQ(beyond, 0U) << "of " << inside << " voxels inside";
}

} // namespace
} // namespace steerseg::test
