// The session layer: what the command line and the kiosk's workflow call. One scan, its texture,
// the solver and the renderer behind operations that speak voxel indices and real units.
#include "session/session.hpp"

// The public header must stay free of GL and EGL (the workflow runs without a GPU).
#if defined(GL_ES_VERSION_2_0) || defined(GL_ES_VERSION_3_0) || defined(EGL_VERSION_1_0)
#error "session/session.hpp pulls in a GL or EGL header"
#endif

#include "core/sample_phantom.hpp"
#include "scan/scan_reader.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_data.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace steerseg::test {
using namespace steerseg::model;
namespace {

class SessionTest : public GpuTest {};

std::size_t insideCount(const std::vector<std::uint8_t>& mask) {
    std::size_t n = 0;
    for (const std::uint8_t m : mask) {
        n += m;
    }
    return n;
}

const Sphere kLesionSeed{glm::vec3(kPhantomLesion.i, kPhantomLesion.j, kPhantomLesion.k), 4.0F};
// T - eps = 610, half-way between the lesion (800) and the brain (420): the front stops where a
// voxel is half lesion (the phantom's partial volume), at the sphere's own boundary.
const LevelSetParams kLesionParams{static_cast<float>(kPhantomLesion.intensity), 190.0F, 0.8F};

TEST_F(SessionTest, SegmentsTheSampleLesionExportsItAndDrawsIt) {
    session::Session s = session::Session::open(scan::kBuiltinSample);
    EXPECT_EQ(s.format(), "builtin");
    EXPECT_FALSE(s.hasLevelSet());
    s.addSeed(kLesionSeed);
    EXPECT_TRUE(s.hasLevelSet());
    s.setParams(kLesionParams);
    const session::RunOutcome run = s.run({session::RunMode::Converge, 2000, 0.0F});
    EXPECT_TRUE(run.result.converged);
    EXPECT_GT(run.solveSeconds, 0.0);
    // The lesion is a 12 mm sphere on 1 x 1 x 1.5 mm voxels.
    const double analytic =
        4.0 / 3.0 * std::numbers::pi * std::pow(kPhantomLesion.radiusMm, 3) / 1.5;
    const double inside = static_cast<double>(insideCount(s.mask()));
    EXPECT_NEAR(inside, analytic, 0.06 * analytic);

    const auto dir = tempDir("session");
    s.exportMask(dir / "lesion.nii.gz");
    const scan::LoadedScan back = scan::readScan(dir / "lesion.nii.gz");
    EXPECT_EQ(back.volume.dims(), s.scan().dims());

    render::ViewParams axial = s.defaultView(render::ViewKind::Axial, {64, 64});
    axial.slice = kPhantomLesion.k;
    const auto frame = s.render(axial);
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(frame->slice, kPhantomLesion.k);
    const RgbaImage picture = s.picture();
    EXPECT_EQ(picture.width, 64);
    int yellow = 0; // the contour
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const std::uint8_t* p = picture.at(x, y);
            yellow += static_cast<int>(p[0] > 200 && p[1] > 200 && p[2] < 80);
        }
    }
    EXPECT_GT(yellow, 10);
}

TEST_F(SessionTest, RefusesSpheresThatDoNotFitTheScan) {
    session::Session s(makeSamplePhantom(), "builtin");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Sphere& bad :
         {Sphere{{64, 64, 48}, 3e9F}, Sphere{{64, 64, 48}, -2.0F}, Sphere{{64, 64, 48}, nan},
          Sphere{{nan, 64, 48}, 3.0F}, Sphere{{-1, 64, 48}, 3.0F}, Sphere{{64, 64, 96}, 3.0F}}) {
        EXPECT_THROW(s.addSeed(bad), std::invalid_argument);
        EXPECT_THROW(s.erase(bad), std::invalid_argument);
    }
    EXPECT_FALSE(s.hasLevelSet());
}

TEST_F(SessionTest, RefusesAMaskOnAnotherGrid) {
    session::Session s(makeSamplePhantom(), "builtin");
    const auto dir = tempDir("session_mask");
    Geometry g;
    g.dims = {16, 16, 16};
    session::Session other(Volume(VoxelType::UInt8, g), "test");
    other.exportMask(dir / "small.nii.gz");
    try {
        s.startFromMask(dir / "small.nii.gz");
        FAIL() << "a 16^3 mask was taken for a 128x128x96 scan";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("mask is 16x16x16 but the scan is 128x128x96"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(s.hasLevelSet());
}

TEST_F(SessionTest, StepsNeedParameters) {
    session::Session s(makeSamplePhantom(), "builtin");
    s.addSeed(kLesionSeed);
    EXPECT_THROW(s.step(1), std::logic_error);
    EXPECT_THROW(s.setParams({800.0F, -1.0F, 0.5F}), std::invalid_argument);
    s.setParams(kLesionParams);
    EXPECT_EQ(s.step(3).iterations, 3);
    EXPECT_EQ(s.stats().iterations, 3);
}

} // namespace
} // namespace steerseg::test
