// steerseg render end to end: the image is written with the asked size and shows the scan;
// bad options exit 2 with a one-line reason, runtime failures exit 1.
#include "render/image.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

int runSteerseg(const std::string& arguments) {
    const char* env = std::getenv("STEERSEG_BINARY");
    const std::string binary = env != nullptr ? env : STEERSEG_CLI_BINARY;
    const int status = std::system((binary + " " + arguments + " 2>/dev/null").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(RenderCli, WritesEachViewOfTheSampleAtTheAskedSize) {
    const auto dir = tempDir("render-cli");
    for (const char* view : {"3d", "sagittal"}) {
        SCOPED_TRACE(view);
        const auto out = dir / (std::string(view) + ".png");
        ASSERT_EQ(runSteerseg(std::string("render --input builtin:sample --view ") + view +
                              " --size 48x40 --output " + out.string()),
                  0);
        const render::RgbaImage img = render::readImage(out);
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

TEST(RenderCli, UnreadableScanOrUnwritableOutputFailsWithStatusOne) {
    EXPECT_EQ(runSteerseg("render --input /nonexistent/scan.nii --output /tmp/x.png"), 1);
    EXPECT_EQ(runSteerseg("render --input builtin:sample --size 16x16 --output "
                          "/nonexistent-dir/out.png"),
              1);
}

} // namespace
} // namespace steerseg::test
