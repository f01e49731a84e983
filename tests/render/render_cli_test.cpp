// steerseg render end to end: the image is written with the asked size and shows the scan;
// bad options exit 2 with a one-line reason, runtime failures exit 1.
#include "core/rgba_image.hpp"
#include "exports/image_file.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

int runSteerseg(const std::string& arguments) {
    return test::runSteerseg(arguments).exitCode;
}

TEST(RenderCli, WritesEachViewOfTheSampleAtTheAskedSize) {
    const auto dir = tempDir("render-cli");
    for (const char* view : {"3d", "sagittal"}) {
        SCOPED_TRACE(view);
        const auto out = dir / (std::string(view) + ".png");
        ASSERT_EQ(runSteerseg(std::string("render --input builtin:sample --view ") + view +
                              " --size 48x40 --output " + out.string()),
                  0);
        const RgbaImage img = exports::readImage(out);
        EXPECT_EQ(img.width, 48);
        EXPECT_EQ(img.height, 40);
        int lit = 0;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                lit += img.at(x, y)[0] > 30 ? 1 : 0;
            }
        }
        EXPECT_GT(lit, 48 * 40 / 5) << "the scan does not show";
    }
    std::filesystem::remove_all(dir);
}

TEST(RenderCli, RejectsBadOptionsWithUsageStatus) {
    // A few representative cases: each run of the binary costs about a second on llvmpipe.
    const std::string base = "render --input builtin:sample --output /tmp/steerseg-never.png ";
    EXPECT_EQ(runSteerseg(base + "--view axial --slice 96"), 2); // sample has 96 slices: 0..95
    EXPECT_EQ(runSteerseg(base + "--view 3d --slice 3"), 2);
    EXPECT_EQ(runSteerseg(base + "--view oblique"), 2);
    EXPECT_EQ(runSteerseg(base + "--clip 0,0,0,1"), 2);
    EXPECT_EQ(runSteerseg(base + "--size 0x10"), 2);
    EXPECT_EQ(runSteerseg(base + "--roi everywhere"), 2);
    EXPECT_FALSE(std::filesystem::exists("/tmp/steerseg-never.png"));
}

TEST(RenderCli, UnreadableScanIsOneUnwritableOutputIsFour) {
    EXPECT_EQ(runSteerseg("render --input /nonexistent/scan.nii --output /tmp/x.png"), 1);
    EXPECT_EQ(runSteerseg("render --input builtin:sample --size 16x16 --output "
                          "/nonexistent-dir/out.png"),
              4);
}

// Yellow contour pixels in an axial slice image.
int yellowPixels(const RgbaImage& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const auto p = img.at(x, y);
            n += (p[0] > 200 && p[1] > 200 && p[2] < 80) ? 1 : 0;
        }
    }
    return n;
}

// The segmentation shown comes from the solver: seeds segment first, and a mask written by
// `segment` draws the same contour when given back with --mask.
TEST(RenderCli, DrawsTheSegmentationFromSeedsOrFromAMask) {
    const auto dir = tempDir("render-cli-seg");
    const std::string seg = "--seed 80,56,52,5 --T 800 --eps 100 --alpha 0.8 --iterations 60";
    const auto mask = dir / "lesion.nii.gz";
    ASSERT_EQ(
        test::runSteerseg("segment --input builtin:sample " + seg + " --output " + mask.string())
            .exitCode,
        0);
    const auto fromSeeds = dir / "seeds.png";
    const auto fromMask = dir / "mask.png";
    const std::string view = " --view axial --slice 52 --size 96x96 --no-labels --output ";
    ASSERT_EQ(runSteerseg("render --input builtin:sample " + seg + view + fromSeeds.string()), 0);
    ASSERT_EQ(runSteerseg("render --input builtin:sample --mask " + mask.string() + view +
                          fromMask.string()),
              0);
    const RgbaImage a = exports::readImage(fromSeeds);
    const RgbaImage b = exports::readImage(fromMask);
    EXPECT_GT(yellowPixels(a), 20) << "no contour drawn from the seeds' segmentation";
    EXPECT_GT(yellowPixels(b), 20) << "no contour drawn from the mask";
    EXPECT_NEAR(yellowPixels(a), yellowPixels(b), 0.2 * yellowPixels(a));
    // A mask and a segmentation to run are two sources of the level set: refused.
    EXPECT_EQ(runSteerseg("render --input builtin:sample --mask " + mask.string() +
                          " --seed 1,1,1,1 --T 1 --eps 1 --alpha 0.5 --iterations 1 --output " +
                          (dir / "x.png").string()),
              2);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
