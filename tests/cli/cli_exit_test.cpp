// The command line's exit statuses (app/cli/commands.hpp): each kind of failure ends with its
// documented status and one line naming the problem; --help lists them all. Seeds and erasers
// that do not fit the scan are refused before any GPU work.
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

const std::string kSegment =
    "segment --input builtin:sample --T 900 --eps 200 --alpha 0.9 --iterations 1 ";

// The one-line message, without the usage line a usage error adds.
std::string firstLine(const std::string& err) {
    return err.substr(0, err.find('\n'));
}

TEST(CliExit, HelpListsEveryExitStatus) {
    const test::CliRun r = test::runSteerseg("--help");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    for (const char* line :
         {"exit status:", "  0  done", "  1  the scan (or --mask) cannot be read",
          "  2  a bad or missing option", "  3  no GPU context", "  4  an output file cannot"}) {
        EXPECT_NE(r.out.find(line), std::string::npos) << line << " missing from\n" << r.out;
    }
    EXPECT_EQ(test::runSteerseg("").exitCode, 2);
    EXPECT_EQ(test::runSteerseg("no-such-command").exitCode, 2);
}

TEST(CliExit, UnreadableScanIsOne) {
    const test::CliRun r = test::runSteerseg("info /nonexistent/scan.nii.gz");
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.err, "steerseg info: /nonexistent/scan.nii.gz: no such file or folder\n");
}

struct BadSphere {
    const char* option;
    const char* message;
};

// 128 x 128 x 96 voxels: a diagonal of 204.9.
TEST(CliExit, SeedsAndErasersThatDoNotFitTheScanAreTwo) {
    const BadSphere cases[] = {
        {"--seed 80,56,52,3e9", "--seed: sphere radius 3e+09 voxels is larger than the volume's "
                                "diagonal (204.9 voxels for 128 x 128 x 96)"},
        {"--seed 80,56,52,-4", "--seed: sphere radius must be a positive number of voxels"},
        {"--seed 80,56,52,0", "--seed: sphere radius must be a positive number of voxels"},
        {"--seed 80,56,52,nan", "--seed: expected a finite number, got 'nan'"},
        {"--seed 80,inf,52,4", "--seed: expected a finite number, got 'inf'"},
        {"--seed 80,56,52,1e300", "--seed: 80,56,52,1e300 holds a number out of range"},
        {"--seed -1,56,52,4", "--seed: sphere centre (-1, 56, 52) lies outside the volume"},
        {"--seed 80,56,3e9,4", "--seed: sphere centre (80, 56, 3e+09) lies outside the volume"},
        {"--seed 80,56,52,4 --erase 80,56,52,1e9", "--erase: sphere radius 1e+09 voxels"},
        {"--seed 80,56,52,4 --erase 80,128,52,2", "--erase: sphere centre (80, 128, 52) lies"},
    };
    const auto dir = test::tempDir("cli-exit-seeds");
    for (const BadSphere& c : cases) {
        const test::CliRun r =
            test::runSteerseg(kSegment + c.option + " --output " + (dir / "m.nii.gz").string());
        EXPECT_EQ(r.exitCode, 2) << c.option << ": " << r.err;
        EXPECT_NE(firstLine(r.err).find(c.message), std::string::npos) << c.option << ": " << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "m.nii.gz")) << c.option;
    }
}

// Mesa looks for its driver under LIBGL_DRIVERS_PATH: pointing it at nothing leaves EGL without
// a device, as on a console whose GPU driver is missing.
TEST(CliExit, NoGpuContextIsThree) {
    ASSERT_EQ(::setenv("LIBGL_DRIVERS_PATH", "/nonexistent", 1), 0);
    const test::CliRun r = test::runSteerseg("gpu-info");
    const test::CliRun s = test::runSteerseg(kSegment + "--seed 80,56,52,4 --output " +
                                             (test::tempDir("cli-exit-gpu") / "m.nrrd").string());
    ::unsetenv("LIBGL_DRIVERS_PATH");
    if (r.exitCode == 0 && r.out.find("Mesa") == std::string::npos) {
        GTEST_SKIP() << "not a Mesa driver: LIBGL_DRIVERS_PATH cannot take the GPU away";
    }
    EXPECT_EQ(r.exitCode, 3) << r.out << r.err;
    EXPECT_NE(r.err.find("steerseg gpu-info: "), std::string::npos) << r.err;
    EXPECT_EQ(s.exitCode, 3) << s.err;
}

// Needs the GPU (the mask is written after the solver ran).
TEST(CliExit, UnwritableOutputIsFour) {
    const auto dir = test::tempDir("cli-exit-write");
    const test::CliRun r = test::runSteerseg(kSegment + "--seed 80,56,52,4 --output " +
                                             (dir / "no/m.nii.gz").string());
    EXPECT_EQ(r.exitCode, 4) << r.err;
    EXPECT_NE(r.err.find("no/m.nii.gz"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the folder " + (dir / "no").string() + " does not exist"),
              std::string::npos)
        << r.err;
    const test::CliRun png =
        test::runSteerseg(kSegment + "--seed 80,56,52,4 --output " + (dir / "m.png").string());
    EXPECT_EQ(png.exitCode, 2) << png.err;
    EXPECT_NE(png.err.find("cannot tell the format from the extension"), std::string::npos)
        << png.err;
    const test::CliRun report =
        test::runSteerseg(kSegment + "--seed 80,56,52,4 --output " + (dir / "ok.nii.gz").string() +
                          " --report " + (dir / "no/r.json").string());
    EXPECT_EQ(report.exitCode, 4) << report.err;
    EXPECT_NE(report.err.find("no/r.json: the folder " + (dir / "no").string() + " does not exist"),
              std::string::npos)
        << report.err;
    const test::CliRun picture = test::runSteerseg("render --input builtin:sample --size 8x8 "
                                                   "--output " +
                                                   (dir / "no/view.png").string());
    EXPECT_EQ(picture.exitCode, 4) << picture.err;
    EXPECT_NE(picture.err.find("no/view.png"), std::string::npos) << picture.err;
}

} // namespace
} // namespace steerseg::test
