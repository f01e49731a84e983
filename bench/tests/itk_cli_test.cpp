// The benchmark tools' command lines: exit codes and the files they write.
#include "itk_image_io.hpp"
#include "support/test_data.hpp"
#include "synthetic_ball.hpp"

#include <cstdlib>
#include <gtest/gtest.h>
#include <string>
#include <sys/wait.h>

namespace steerseg::itkbench {
namespace {

int runTool(const std::string& binary, const std::string& args) {
    const std::string cmd = binary + " " + args + " >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class ItkCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = steerseg::test::tempDir("itk-cli");
        scan_ = (dir_ / "ball.nii.gz").string();
        const FloatImage::Pointer ball = test::syntheticBall(8.0, 100.0F, 0.0F);
        writeMask(scan_, test::thresholdMask(ball, 50.0F)); // a 0/1 scan is enough here
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::filesystem::path dir_;
    std::string scan_;
};

TEST_F(ItkCli, SegmentsAndWritesAMaskOnTheScanGrid) {
    const std::string mask = (dir_ / "mask.nii.gz").string();
    const std::string report = (dir_ / "report.json").string();
    ASSERT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY,
                      "--input " + scan_ + " --seed 16,16,16,3 --T 1 --eps 0.5 --alpha 0.8 " +
                          "--iterations 20 --output " + mask + " --report " + report),
              0);
    EXPECT_TRUE(std::filesystem::exists(report));
    EXPECT_EQ(runTool(STEERSEG_MASK_DICE_BINARY, scan_ + " " + mask), 0);
}

TEST_F(ItkCli, UsageErrorsExitTwoAndRuntimeErrorsOne) {
    const std::string out = "--output " + (dir_ / "m.nii.gz").string();
    const std::string base = "--input " + scan_ + " --T 1 --eps 0.5 --alpha 0.8 " + out;
    EXPECT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY, base + " --converge"), 2);        // no seed
    EXPECT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY, base + " --seed 16,16,16,3"), 2); // no stop
    EXPECT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY,
                      base + " --seed 16,16,16,3 --converge --iterations 5"),
              2);
    EXPECT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY, base + " --seed 99,16,16,3 --converge"), 1);
    EXPECT_EQ(runTool(STEERSEG_ITK_LEVELSET_BINARY,
                      "--input " + (dir_ / "missing.nii.gz").string() +
                          " --T 1 --eps 1 --alpha 1 --seed 1,1,1,1 --converge " + out),
              1);
    EXPECT_EQ(runTool(STEERSEG_MASK_DICE_BINARY, scan_), 2);
}

TEST_F(ItkCli, DiceRefusesMasksOnDifferentGrids) {
    const std::string other = (dir_ / "other.nii.gz").string();
    auto small = test::thresholdMask(test::syntheticBall(8.0, 100.0F, 0.0F), 50.0F);
    MaskImage::SpacingType spacing;
    spacing.Fill(1.0);
    small->SetSpacing(spacing);
    writeMask(other, small);
    EXPECT_EQ(runTool(STEERSEG_MASK_DICE_BINARY, scan_ + " " + other), 1);
}

} // namespace
} // namespace steerseg::itkbench
