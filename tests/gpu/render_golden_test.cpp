// Golden images of every view kind, rendered on Mesa llvmpipe from a small synthetic scene.
// STEERSEG_UPDATE_GOLDEN=1 rewrites tests/golden/*.png (see docs/renderer.md).
#include "render/renderer.hpp"
#include "render_scene.hpp"
#include "support/gpu_fixture.hpp"

namespace steerseg::test {
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

} // namespace
} // namespace steerseg::test
