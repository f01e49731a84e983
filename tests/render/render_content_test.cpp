// Content checks that a blank or wrongly placed picture cannot pass: the clip plane's yellow
// line lies where the plane meets a known sphere, ROI mode shows nothing outside the surface,
// the slice contour is the mask's boundary, the surface covers its projected disc.
#include "render/renderer.hpp"
#include "render_scene.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

using render::ViewKind;

constexpr glm::ivec3 kDims{40, 40, 40};
constexpr glm::dvec3 kCentre{20.0, 20.0, 20.0};
constexpr double kRadius = 10.0;

Geometry unitGeometry(const glm::ivec3& dims) {
    Geometry g;
    g.dims = dims;
    return g; // 1 mm voxels, origin 0, identity direction: world == index
}

// The world ray through a pixel, as the ray caster builds it.
glm::dvec3 pixelRay(const render::Camera& cam, const glm::ivec2& size, int x, int y) {
    const glm::dvec2 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (y + 0.5) / size.y * 2.0);
    return cam.rayDirection(ndc, static_cast<double>(size.x) / size.y);
}

double rayDistanceTo(const render::Camera& cam, const glm::dvec3& dir, const glm::dvec3& point) {
    const glm::dvec3 rel = point - cam.eye();
    return glm::length(rel - dir * glm::dot(rel, dir));
}

class RenderContent : public GpuTest {
  protected:
    render::TransferFunction flatTransfer(double value) {
        render::TransferFunction tf;
        tf.widgets.push_back({value, 200.0, 0.0, {0.9, 0.9, 0.9}, 0.3});
        return tf;
    }
};

TEST_F(RenderContent, ClipPlaneLineLiesWherePlaneMeetsSphere) {
    const Volume scan = makeScan(unitGeometry(kDims), [](glm::ivec3 v) {
        return static_cast<float>(100 + 10 * ((v.x / 4 + v.z / 4) % 2)); // textured plane
    });
    render::Renderer renderer(scan);
    GpuPool pool(spherePool(kDims, kCentre, kRadius));
    const BrickPoolView view = pool.view();
    render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {128, 128});
    p.camera.orbit(20.0, 15.0);
    p.clip = {true, {0.0, -1.0, 0.0}, -kCentre.y}; // cut away y < 20
    p.window = {105.0, 40.0};                      // 100 and 110 both mid-grey
    renderer.render(p, &view);
    const RgbaImage img = renderer.readback();

    std::vector<int> anglesHit(24, 0);
    int yellow = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const glm::dvec3 dir = pixelRay(p.camera, p.size, x, y);
            const double t = (kCentre.y - p.camera.eye().y) / dir.y;
            const glm::dvec3 hit = p.camera.eye() + t * dir;
            const bool onPlane = glm::all(glm::greaterThan(hit, glm::dvec3(-0.5))) &&
                                 glm::all(glm::lessThan(hit, glm::dvec3(kDims) - 0.5));
            const double r = glm::length(glm::dvec2(hit.x - kCentre.x, hit.z - kCentre.z));
            const bool isLine = isYellow(img.at(x, y));
            if (isLine) {
                ++yellow;
                ASSERT_TRUE(onPlane) << "yellow off the plane at pixel " << x << "," << y;
                EXPECT_NEAR(r, kRadius, 1.0) << "yellow pixel " << x << "," << y;
                const double angle = std::atan2(hit.z - kCentre.z, hit.x - kCentre.x);
                const auto bin =
                    static_cast<std::size_t>(std::floor((angle + M_PI) / (2.0 * M_PI) * 24.0));
                ++anglesHit[std::min<std::size_t>(bin, 23)];
            } else if (onPlane && std::abs(r - kRadius) > 2.0) {
                // The cut face shows the scan in grey.
                const std::uint8_t* px = img.at(x, y);
                EXPECT_TRUE(px[0] == px[1] && px[1] == px[2] && px[0] > 50)
                    << "plane pixel " << x << "," << y << " not grey";
            }
        }
    }
    EXPECT_GT(yellow, 60);
    for (std::size_t b = 0; b < anglesHit.size(); ++b) {
        EXPECT_GT(anglesHit[b], 0) << "the circle has a gap in angle bin " << b;
    }
}

TEST_F(RenderContent, RoiInsideShowsNoScanOutsideSurface) {
    const Volume scan = makeScan(unitGeometry(kDims), [](glm::ivec3) { return 500.0F; });
    render::Renderer renderer(scan);
    GpuPool pool(spherePool(kDims, kCentre, kRadius));
    const BrickPoolView view = pool.view();
    render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {96, 96});
    p.transfer = flatTransfer(500.0);
    p.surface = render::SurfaceMode::Hidden;
    p.roi = render::RoiMode::Inside;
    renderer.render(p, &view);
    const RgbaImage inside = renderer.readback();
    p.roi = render::RoiMode::Off;
    renderer.render(p, &view);
    const RgbaImage off = renderer.readback();
    p.roi = render::RoiMode::Dim;
    renderer.render(p, &view);
    const RgbaImage dim = renderer.readback();

    int checkedOutside = 0;
    int checkedInside = 0;
    for (int y = 0; y < inside.height; ++y) {
        for (int x = 0; x < inside.width; ++x) {
            const glm::dvec3 dir = pixelRay(p.camera, p.size, x, y);
            const double d = rayDistanceTo(p.camera, dir, kCentre);
            if (d > kRadius + 1.0) {
                EXPECT_TRUE(isBlack(inside.at(x, y))) << "scan shown outside at " << x << "," << y;
                ++checkedOutside;
                if (!isBlack(off.at(x, y))) {
                    EXPECT_LT(dim.at(x, y)[0], off.at(x, y)[0])
                        << "not dimmed at " << x << "," << y;
                }
            } else if (d < kRadius - 2.0) {
                EXPECT_FALSE(isBlack(inside.at(x, y))) << "ROI empty at " << x << "," << y;
                ++checkedInside;
            }
        }
    }
    EXPECT_GT(checkedOutside, 1000);
    EXPECT_GT(checkedInside, 200);
    // The plain mode shows the scan outside the surface (so the check above means something).
    EXPECT_FALSE(isBlack(off.at(18, 48)));
    EXPECT_FALSE(isBlack(dim.at(18, 48)));
}

TEST_F(RenderContent, OpaqueSurfaceCoversItsDiscAcrossBrickSizes) {
    const Volume scan = makeScan(unitGeometry(kDims), [](glm::ivec3) { return 0.0F; });
    render::Renderer renderer(scan);
    render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {96, 96});
    p.transfer.widgets.clear();
    RgbaImage images[2];
    const int brickSizes[2] = {8, 4};
    for (int n = 0; n < 2; ++n) {
        GpuPool pool(spherePool(kDims, kCentre, kRadius, brickSizes[n]));
        const BrickPoolView view = pool.view();
        renderer.render(p, &view);
        images[n] = renderer.readback();
    }
    for (int y = 0; y < 96; ++y) {
        for (int x = 0; x < 96; ++x) {
            const double d = rayDistanceTo(p.camera, pixelRay(p.camera, p.size, x, y), kCentre);
            const std::uint8_t* px = images[0].at(x, y);
            if (d < kRadius - 1.0) {
                EXPECT_TRUE(px[0] > px[2] && px[0] > 20) << "no surface at " << x << "," << y;
            } else if (d > kRadius + 1.0) {
                EXPECT_TRUE(isBlack(px)) << "surface outside its disc at " << x << "," << y;
            }
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(px[c], images[1].at(x, y)[c], 3)
                    << "brick size changed " << x << "," << y;
            }
        }
    }
}

// The opaque surface's search skips what cannot hold the surface (beyond the box of bricks
// that are not constant outside, and inside constant bricks); the joint loop of the region of
// interest modes walks every sample. With the ROI dimmed by 1 (no dimming) both draw the same
// picture, so a skip too far shows as a lost piece of surface: small spheres (a few samples
// across, one on a brick corner) are what a skip past a seam or the box's edge loses first.
// (Every surface lies PHI_FAR voxels inside the stored bricks, so a skip wrong by less than
// that draws the same picture: checked by hand, a box 4 voxels short or a skip 8 samples too
// far passes, a box 12 short or a skip 16 too far fails.)
// Also a surface cut by the volume's low faces and one cut by its high faces (rays that start
// inside it), and one in the middle whose box ends short of every face.
TEST_F(RenderContent, OpaqueSurfaceSearchFindsWhatEverySampleFinds) {
    constexpr glm::ivec3 dims{64, 64, 64};
    const Volume scan = makeScan(unitGeometry(dims), [](glm::ivec3 v) {
        return 300.0F + 5.0F * static_cast<float>(v.x + v.y + v.z);
    });
    render::Renderer renderer(scan);
    struct Scene {
        const char* name;
        std::function<float(glm::ivec3)> phi;
    };
    const auto sphere = [](glm::dvec3 c, double r) {
        return
            [c, r](glm::ivec3 v) { return static_cast<float>(glm::length(glm::dvec3(v) - c) - r); };
    };
    const Scene scenes[] = {
        {"middle", sphere({32.0, 30.0, 33.0}, 8.0)},
        {"low faces", sphere({2.0, 3.0, 1.0}, 12.0)},
        {"high faces", sphere({61.0, 62.0, 63.0}, 12.0)},
        {"small ones",
         [a = sphere({8.0, 8.0, 8.0}, 2.0), b = sphere({20.0, 44.0, 36.0}, 2.0),
          c = sphere({47.5, 23.5, 40.0}, 1.5), d = sphere({40.0, 40.0, 16.0}, 3.0)](glm::ivec3 v) {
             return std::min({a(v), b(v), c(v), d(v)});
         }},
    };
    for (const Scene& scene : scenes) {
        GpuPool pool(packPhi(densePhi(dims, scene.phi), dims, 8, 4.0F));
        const BrickPoolView view = pool.view();
        for (const double yaw : {0.0, 135.0}) {
            render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {96, 96});
            p.transfer = flatTransfer(600.0);
            p.transfer.widgets[0].opacity = 0.03;
            p.camera.orbit(yaw, 20.0);
            p.surface = render::SurfaceMode::Opaque;
            p.roi = render::RoiMode::Off;
            renderer.render(p, &view);
            const RgbaImage searched = renderer.readback();
            p.roi = render::RoiMode::Dim;
            p.dimFactor = 1.0F;
            renderer.render(p, &view);
            const RgbaImage walked = renderer.readback();
            int surfacePixels = 0;
            int differing = 0;
            for (int y = 0; y < searched.height; ++y) {
                for (int x = 0; x < searched.width; ++x) {
                    const std::uint8_t* a = searched.at(x, y);
                    const std::uint8_t* b = walked.at(x, y);
                    surfacePixels += b[0] > b[2] + 40 ? 1 : 0; // the surface is orange
                    bool same = true;
                    for (int c = 0; c < 3; ++c) {
                        same = same && std::abs(int(a[c]) - int(b[c])) <= 2;
                    }
                    differing += same ? 0 : 1;
                }
            }
            EXPECT_EQ(differing, 0) << scene.name << ", yaw " << yaw;
            EXPECT_GT(surfacePixels, 20) << scene.name << ", yaw " << yaw << ": no surface drawn";
        }
    }
}

TEST_F(RenderContent, SliceContourIsTheMaskBoundary) {
    const glm::ivec3 dims{40, 36, 12};
    auto inMask = [](int i, int j) {
        const double ex = (i - 14.0) / 9.0;
        const double ey = (j - 20.0) / 6.0;
        return ex * ex + ey * ey < 1.0 || (i >= 24 && i < 34 && j >= 5 && j < 13);
    };
    const Volume scan = makeScan(unitGeometry(dims), [](glm::ivec3) { return 10.0F; });
    render::Renderer renderer(scan);
    const std::vector<float> phi =
        densePhi(dims, [&](glm::ivec3 v) { return inMask(v.x, v.y) ? -0.5F : 0.5F; });
    GpuPool pool(packPhi(phi, dims, 8, 4.0F));
    const BrickPoolView view = pool.view();
    render::ViewParams p = renderer.defaultParams(ViewKind::Axial, {dims.x, dims.y});
    p.slice = 6;
    p.labels = false;
    renderer.render(p, &view);
    const RgbaImage img = renderer.readback();
    int boundary = 0;
    for (int y = 0; y < dims.y; ++y) {
        for (int x = 0; x < dims.x; ++x) {
            // Identity direction: screen right = +i, screen down = +j (anterior is up).
            const bool here = inMask(x, y);
            const bool expected = (x + 1 < dims.x && inMask(x + 1, y) != here) ||
                                  (y + 1 < dims.y && inMask(x, y + 1) != here);
            boundary += expected ? 1 : 0;
            EXPECT_EQ(isYellow(img.at(x, y)), expected) << "pixel " << x << "," << y;
        }
    }
    EXPECT_GT(boundary, 50);
}

TEST_F(RenderContent, SpeedViewColoursPositiveAndNegativeApart) {
    const Volume scan = makeHeadScene();
    render::Renderer renderer(scan);
    render::ViewParams p = renderer.defaultParams(ViewKind::Axial, {48, 48});
    p.slice = static_cast<int>(kHeadLesionCentre.z);
    p.content = render::SliceContent::Speed;
    p.speed = {900.0, 100.0};
    p.labels = false;
    renderer.render(p, nullptr);
    const RgbaImage img = renderer.readback();
    // 1:1 here (48 voxels of 1.2 mm across 48 pixels); axial with identity: x = i, y = j.
    const std::uint8_t* lesion = img.at(31, 19);
    const std::uint8_t* brain = img.at(18, 28);
    EXPECT_GT(lesion[1], lesion[2] + 60) << "positive speed not green";
    EXPECT_GT(brain[2], brain[1] + 60) << "negative speed not blue";
}

} // namespace
} // namespace steerseg::test
