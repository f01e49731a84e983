// Golden images of every view kind, rendered on Mesa llvmpipe from a small synthetic scene.
// STEERSEG_UPDATE_GOLDEN=1 rewrites tests/golden/*.png (see docs/renderer.md).
#include "exports/image_file.hpp"
#include "golden_compare.hpp"
#include "render/renderer.hpp"
#include "render_scene.hpp"
#include "support/gpu_fixture.hpp"

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

using render::ViewKind;

class RenderGolden : public GpuTest {
  protected:
    void SetUp() override {
        GpuTest::SetUp();
        scan_ = makeHeadScene();
        renderer_ = std::make_unique<render::Renderer>(scan_);
        pool_ = std::make_unique<GpuPool>(
            spherePool(scan_.dims(), kHeadLesionCentre, kHeadLesionRadius));
    }
    void expectGolden(const std::string& name, const render::ViewParams& params, bool surface) {
        const BrickPoolView view = pool_->view();
        renderer_->render(params, surface ? &view : nullptr);
        const GoldenResult r = compareGolden(name, renderer_->readback());
        EXPECT_TRUE(r.ok) << r.message;
    }
    Volume scan_;
    std::unique_ptr<render::Renderer> renderer_;
    std::unique_ptr<GpuPool> pool_;
};

TEST_F(RenderGolden, VolumeWithOpaqueSurface) {
    render::ViewParams p = renderer_->defaultParams(ViewKind::Volume3d, {128, 128});
    p.camera.orbit(30.0, 20.0);
    expectGolden("volume_surface", p, true);
}

TEST_F(RenderGolden, VolumeClippedWithDimmedRoi) {
    render::ViewParams p = renderer_->defaultParams(ViewKind::Volume3d, {128, 128});
    p.camera.orbit(-25.0, 15.0);
    p.clip = {true, {0.0, -1.0, 0.0}, -kHeadLesionCentre.y};
    p.roi = render::RoiMode::Dim;
    p.surface = render::SurfaceMode::Translucent;
    expectGolden("volume_clip_dim", p, true);
}

TEST_F(RenderGolden, AxialWithContour) {
    render::ViewParams p = renderer_->defaultParams(ViewKind::Axial, {128, 128});
    p.slice = static_cast<int>(kHeadLesionCentre.z);
    expectGolden("axial_contour", p, true);
}

TEST_F(RenderGolden, SagittalSpeed) {
    render::ViewParams p = renderer_->defaultParams(ViewKind::Sagittal, {128, 128});
    p.slice = static_cast<int>(kHeadLesionCentre.x);
    p.content = render::SliceContent::Speed;
    p.speed = {900.0, 150.0};
    expectGolden("sagittal_speed", p, true);
}

TEST_F(RenderGolden, CoronalZoomedPannedWithoutSurface) {
    render::ViewParams p = renderer_->defaultParams(ViewKind::Coronal, {160, 128});
    p.zoom = 1.6;
    p.pan = {8.0, -4.0};
    expectGolden("coronal_zoom", p, false);
}

// The comparison itself, on the committed goldens (no GPU needed).

RgbaImage eraseYellow(RgbaImage image, int& erased) {
    erased = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            std::uint8_t* px = image.at(x, y);
            if (isYellow(px)) {
                px[0] = px[1] = px[2] = 90; // the grey of the scan around it
                ++erased;
            }
        }
    }
    return image;
}

// A picture that lost its yellow line (the slice contour, or the clip plane's intersection with
// the surface) must not match its golden, however few pixels the line covers.
TEST(GoldenComparison, FailsWhenTheContourOrClipLineIsErased) {
    for (const char* name : {"axial_contour", "volume_clip_dim"}) {
        SCOPED_TRACE(name);
        const RgbaImage golden = exports::readImage(goldenPath(name));
        ASSERT_TRUE(compareImages(name, golden, golden).ok);
        int erased = 0;
        const RgbaImage without = eraseYellow(golden, erased);
        ASSERT_GT(erased, 20) << "the golden shows no yellow line";
        // Colour and alpha alone (the comparison before the yellow check) let the axial
        // contour vanish: it is under the 1% differing-pixel budget.
        if (std::string(name) == "axial_contour") {
            GoldenTolerance colourOnly;
            colourOnly.yellowCountTolerance = 1e9;
            EXPECT_TRUE(compareImages(name, golden, without, colourOnly).ok)
                << erased << " yellow pixels: past the pixel budget, so this no longer shows "
                << "the gap the yellow check closes";
        }
        const GoldenResult r = compareImages(name, golden, without);
        EXPECT_FALSE(r.ok);
        EXPECT_NE(r.message.find("0 contour-yellow pixels where the golden has " +
                                 std::to_string(erased)),
                  std::string::npos)
            << r.message;
    }
}

// Alpha is compared like the colour channels: a picture gone transparent does not match.
TEST(GoldenComparison, FailsWhenOnlyAlphaDiffers) {
    const RgbaImage golden = exports::readImage(goldenPath("volume_surface"));
    RgbaImage clear = golden;
    for (int y = 0; y < clear.height / 4; ++y) {
        for (int x = 0; x < clear.width; ++x) {
            clear.at(x, y)[3] = static_cast<std::uint8_t>(golden.at(x, y)[3] > 127 ? 0 : 255);
        }
    }
    const GoldenResult r = compareImages("volume_surface", golden, clear);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.message.find("alpha 255"), std::string::npos) << r.message;
}

// A view without a surface has no yellow; one with a contour keeps it within the tolerance.
TEST(GoldenComparison, YellowCountTolerance) {
    const RgbaImage golden = exports::readImage(goldenPath("axial_contour"));
    int erased = 0;
    (void)eraseYellow(golden, erased);
    RgbaImage fewer = golden;
    int removed = 0;
    const int keep = erased - static_cast<int>(0.1 * erased); // 10% fewer: within 20%
    int seen = 0;
    for (int y = 0; y < fewer.height; ++y) {
        for (int x = 0; x < fewer.width; ++x) {
            if (isYellow(fewer.at(x, y)) && ++seen > keep) {
                fewer.at(x, y)[2] = 255;
                ++removed;
            }
        }
    }
    ASSERT_GT(removed, 0);
    EXPECT_TRUE(compareImages("axial_contour", golden, fewer).ok);
}

} // namespace
} // namespace steerseg::test
