// The 3D view's picture quality, on pictures where a defect is measurable: a uniform slab must
// show no wood-grain rings (nor the noise a jitter alone would trade them for), and a sphere
// on thick slices must be shaded with the sphere's own normals, not the facets and terraces of
// trilinear phi, whether its level set is a distance (the solver's) or a binary mask's.
#include "render/renderer.hpp"
#include "render_scene.hpp"
#include "solver/phi_init.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace steerseg::test {
namespace {

using render::ViewKind;

// The picture's red channel against its own 5x5 box blur, away from the border: rings are
// steps of a whole sample's opacity where the ray's length through the slab crosses a
// multiple of the step; the blur spreads a step over five pixels, so it stands out by about
// that opacity. Smooth shading (the slab seen at a changing angle) survives the blur.
int largestDifferenceFromBlur(const RgbaImage& image) {
    int largest = 0;
    for (int y = 2; y < image.height - 2; ++y) {
        for (int x = 2; x < image.width - 2; ++x) {
            int sum = 0;
            for (int dy = -2; dy <= 2; ++dy) {
                for (int dx = -2; dx <= 2; ++dx) {
                    sum += image.at(x + dx, y + dy)[0];
                }
            }
            const int blurred = (sum + 12) / 25;
            largest = std::max(largest, std::abs(int(image.at(x, y)[0]) - blurred));
        }
    }
    return largest;
}

// How much the picture's red, averaged over rings one pixel wide around its centre, rises
// from the centre out to `radius` pixels (the sum of the rises from one ring to the next).
double radialRise(const RgbaImage& image, int radius) {
    std::vector<double> sum(static_cast<std::size_t>(radius), 0.0);
    std::vector<int> count(sum.size(), 0);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double r = std::hypot(x + 0.5 - 0.5 * image.width, y + 0.5 - 0.5 * image.height);
            const auto ring = static_cast<std::size_t>(r);
            if (ring < sum.size()) {
                sum[ring] += image.at(x, y)[0];
                ++count[ring];
            }
        }
    }
    double rise = 0.0;
    for (std::size_t n = 1; n < sum.size(); ++n) {
        rise += std::max(0.0, sum[n] / count[n] - sum[n - 1] / count[n - 1]);
    }
    return rise;
}

class RenderQuality : public GpuTest {};

TEST_F(RenderQuality, UniformSlabShowsNoRings) {
    // One value throughout but a corner voxel out of sight (the scan needs a range), seen from
    // above at an angle: the rays' lengths through the 4 mm slab vary smoothly over the
    // picture, across about 15 multiples of the sample step, each worth 4 to 10 of 255.
    Geometry g;
    g.dims = {64, 64, 4};
    const Volume scan =
        makeScan(g, [](glm::ivec3 v) { return v == glm::ivec3(63, 63, 3) ? 0.0F : 500.0F; });
    render::Renderer renderer(scan);
    render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {128, 128});
    p.camera = render::Camera::preset(render::CameraPreset::Superior, render::volumeCentre(g),
                                      render::volumeExtentMm(g));
    p.camera.orbit(0.0, -45.0);
    p.camera.zoom(3.0);
    p.transfer.widgets.clear();
    p.transfer.widgets.push_back({500.0, 100.0, 0.0, {0.9, 0.9, 0.9}, 0.2});
    renderer.render(p, nullptr);
    const RgbaImage picture = renderer.readback();
    int lit = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            lit += picture.at(x, y)[0] > 20 ? 1 : 0;
        }
    }
    ASSERT_EQ(lit, picture.width * picture.height) << "the slab does not fill the picture";
    EXPECT_LE(largestDifferenceFromBlur(picture), 2)
        << "the slab's picture has steps (rings) or noise its blurred copy has not";
}

// Mean and worst difference (0..255, red channel) between the rendered sphere and its shading
// from the analytic normal, over the pixels at least `rimMm` inside its outline.
struct ShadingError {
    double mean = 0.0;
    int worst = 0;
    int pixels = 0;
};

ShadingError sphereShadingError(const RgbaImage& image, const render::Camera& cam,
                                const glm::dvec3& centre, double radius, double rimMm) {
    ShadingError e;
    const glm::ivec2 size(image.width, image.height);
    double sum = 0.0;
    for (int y = 0; y < size.y; ++y) {
        for (int x = 0; x < size.x; ++x) {
            const glm::dvec2 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (y + 0.5) / size.y * 2.0);
            const glm::dvec3 dir =
                glm::normalize(cam.rayDirection(ndc, static_cast<double>(size.x) / size.y));
            const glm::dvec3 rel = centre - cam.eye();
            const double along = glm::dot(rel, dir);
            const double miss = glm::length(rel - along * dir);
            if (miss > radius - rimMm) {
                continue;
            }
            const glm::dvec3 hit =
                cam.eye() + dir * (along - std::sqrt(radius * radius - miss * miss));
            // shaders/render/raycast.comp's shade(): a two-sided headlight, Blinn-Phong.
            const double diffuse = std::abs(glm::dot(glm::normalize(hit - centre), dir));
            const double expected = 0.95 * (0.25 + 0.75 * diffuse) + 0.25 * std::pow(diffuse, 24);
            const int want = static_cast<int>(std::lround(std::min(expected, 1.0) * 255.0));
            const int d = std::abs(int(image.at(x, y)[0]) - want);
            sum += d;
            e.worst = std::max(e.worst, d);
            ++e.pixels;
        }
    }
    e.mean = e.pixels > 0 ? sum / e.pixels : 0.0;
    return e;
}

class SphereOnThickSlices : public GpuTest {
  protected:
    // 1 x 1 x 3 mm voxels, a 13 mm sphere: 26 voxels across in-plane, under 9 slices deep.
    static Geometry geometry() {
        Geometry g;
        g.dims = {40, 40, 14};
        g.spacing = {1.0, 1.0, 3.0};
        return g;
    }
    static glm::dvec3 world(glm::ivec3 v) { return glm::dvec3(v) * geometry().spacing; }
    static constexpr glm::dvec3 kCentre{20.0, 20.0, 20.5}; // world mm
    static constexpr double kRadius = 13.0;

    static std::vector<std::uint8_t> sphereMask() {
        const Geometry g = geometry();
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(g.dims.x) * g.dims.y * g.dims.z);
        for (int k = 0; k < g.dims.z; ++k) {
            for (int j = 0; j < g.dims.y; ++j) {
                for (int i = 0; i < g.dims.x; ++i) {
                    mask[i + g.dims.x * (j + g.dims.y * k)] =
                        glm::length(world({i, j, k}) - kCentre) < kRadius ? 1 : 0;
                }
            }
        }
        return mask;
    }

    // The sphere as a scan with partial volume: each voxel the fraction of its extent inside
    // (8 x 8 x 8 points), times kBright. Its half-way value lies on the sphere.
    static constexpr float kBright = 1000.0F;
    // The threshold speed whose zero crossing is the scan's half-way value.
    static constexpr render::SpeedParams kSpeed{kBright, 0.5F * kBright, true};
    static Volume partialVolumeSphere() {
        return makeScan(geometry(), [](glm::ivec3 v) {
            int inside = 0;
            for (int n = 0; n < 512; ++n) {
                const glm::dvec3 at =
                    glm::dvec3(v) - 0.4375 + 0.125 * glm::dvec3(n & 7, (n >> 3) & 7, n >> 6);
                inside += glm::length(at * geometry().spacing - kCentre) < kRadius ? 1 : 0;
            }
            return kBright * static_cast<float>(inside) / 512.0F;
        });
    }

    // `speed`: the data term that moved phi (placesSurface), read from the scan itself.
    ShadingError render(const std::vector<float>& phi, const Volume* scanGiven = nullptr,
                        render::SpeedParams speed = {}) {
        const Geometry g = geometry();
        const Volume ramp = makeScan(g, [](glm::ivec3 v) { return float(v.x); });
        render::Renderer renderer(scanGiven != nullptr ? *scanGiven : ramp);
        GpuPool pool(packPhi(phi, g.dims, 8, 4.0F));
        const solver::BrickPoolView view = pool.view();
        render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {128, 128});
        p.transfer.widgets.clear(); // the surface alone
        p.surface = render::SurfaceMode::Opaque;
        p.camera.orbit(30.0, 10.0); // the slices' planes across the view
        p.camera.zoom(1.6);
        p.speed = speed;
        renderer.render(p, &view);
        const ShadingError e =
            sphereShadingError(renderer.readback(), p.camera, kCentre, kRadius, 1.5);
        EXPECT_GT(e.pixels, 2000) << "the sphere is too small in the picture to judge";
        return e;
    }
};

// Figures on llvmpipe (mean / worst of 255): this renderer 0.7 / 3 on the distance, 16.3 / 109
// on the mask's staircase, 6.5 / 41 on the smoothed mask; with trilinear phi's normals (the
// renderer before) 0.4 / 3, 21.1 / 126 and 7.9 / 46.
TEST_F(SphereOnThickSlices, DistanceLevelSetShadedWithTheSpheresNormals) {
    // phi as the solver keeps it: a distance in voxels (here of the thick axis, so it grows by
    // at most one per voxel on every axis). Smooth already: a wrong reconstruction shows.
    const std::vector<float> phi = densePhi(geometry().dims, [](glm::ivec3 v) {
        return static_cast<float>((glm::length(world(v) - kCentre) - kRadius) / 3.0);
    });
    const ShadingError e = render(phi);
    EXPECT_LT(e.mean, 1.5) << "the shading is " << e.mean << " off on average";
    EXPECT_LT(e.worst, 8) << "the shading is " << e.worst << " off at worst";
}

// A faceted sphere: the staircase of its voxels on thick slices, as a mask's distance
// (solver::maskToPhi). Shaded from the smooth reconstruction its facets and terraces are
// softened; from trilinear phi's normals every voxel face shows.
TEST_F(SphereOnThickSlices, FacetedSphereShadedFromTheSmoothReconstruction) {
    const ShadingError e = render(solver::maskToPhi(sphereMask(), geometry().dims));
    EXPECT_LT(e.mean, 18.5) << "faceted: the shading is " << e.mean << " off on average";
}

// A mask (steerseg render --mask, a resumed session, an undo) goes to the solver through
// smoothMaskPhi (Session::setMask): the same voxels, its staircase rounded off between them.
TEST_F(SphereOnThickSlices, MaskSmoothedBeforeItIsDrawn) {
    const std::vector<std::uint8_t> mask = sphereMask();
    const std::vector<float> phi = solver::smoothMaskPhi(mask, geometry().dims);
    EXPECT_EQ(solver::insideMask(phi), mask) << "smoothing moved a voxel across the surface";
    const ShadingError smooth = render(phi);
    const ShadingError raw = render(solver::maskToPhi(mask, geometry().dims));
    EXPECT_LT(smooth.mean, 7.2) << "blocky: the shading is " << smooth.mean << " off on average";
    EXPECT_LT(smooth.mean, 0.5 * raw.mean);
}

// A level set at convergence is a step: the data term drives phi to its clamp on both sides of
// the front, so its zero sits half-way between voxel centres as a mask's does. Drawn from phi
// alone it shows the voxels; with the data term that moved it (threshold, D = 0 at the
// partial-volume scan's half-way value, on the sphere) the surface lies where the scan puts
// the boundary between them, and is shaded with the sphere's normals.
TEST_F(SphereOnThickSlices, ConvergedStepDrawnAtTheDataTermsCrossing) {
    const std::vector<std::uint8_t> mask = sphereMask();
    std::vector<float> phi(mask.size());
    for (std::size_t n = 0; n < mask.size(); ++n) {
        phi[n] = mask[n] != 0 ? -3.9F : 3.8F; // as measured on the solver's converged lesion
    }
    const Volume scan = partialVolumeSphere();
    const ShadingError step = render(phi, &scan);
    const ShadingError data = render(phi, &scan, kSpeed);
    EXPECT_LT(data.mean, 5.0) << "the shading is " << data.mean << " off on average";
    EXPECT_LT(data.mean, 0.3 * step.mean) << "phi alone: " << step.mean;
}

// The sphere's scan volume-rendered from above (no level set): a boundary widget on the
// gradient axis, as the presets draw a head's skin and skull. Each 3 mm slice of the dome seen
// from above was a ring: on a boundary about a voxel wide the central difference's largest
// value swings with where the boundary falls between two voxels, and the gradient axis turned
// that into opacity (render/gradient.comp). A dome lit by a headlight darkens from its middle
// outwards; a ring is where it brightens again.
TEST_F(SphereOnThickSlices, VolumeRenderedDomeShowsNoSliceRings) {
    const Volume scan = partialVolumeSphere();
    render::Renderer renderer(scan);
    render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {128, 128});
    p.camera = render::Camera::preset(render::CameraPreset::Superior, kCentre,
                                      render::volumeExtentMm(geometry()));
    p.camera.zoom(2.0);
    p.transfer.widgets.clear();
    p.transfer.widgets.push_back({kSpeed.T, kSpeed.eps, 0.3, {0.9, 0.8, 0.7}, 0.3});
    renderer.render(p, nullptr);
    // Llvmpipe: 9.0 with the central difference, 0.2 with the wider one.
    const double rise = radialRise(renderer.readback(), 50);
    EXPECT_LT(rise, 1.0) << "the dome's picture has rings: it brightens by " << rise
                         << " of 255 outwards";
}

// Where phi is a distance (a front still moving, a seed), the data term does not move the
// surface: it is drawn as from phi alone.
TEST_F(SphereOnThickSlices, DistanceLevelSetKeptWhereTheDataTermDisagrees) {
    // The scan's boundary 3 mm outside phi's: D > 0 on both sides of phi's zero.
    const Volume scan = makeScan(geometry(), [](glm::ivec3 v) {
        return glm::length(world(v) - kCentre) < kRadius + 3.0 ? kBright : 0.0F;
    });
    const std::vector<float> phi = densePhi(geometry().dims, [](glm::ivec3 v) {
        return static_cast<float>((glm::length(world(v) - kCentre) - kRadius) / 3.0);
    });
    const ShadingError e = render(phi, &scan, kSpeed);
    EXPECT_LT(e.mean, 1.5) << "the shading is " << e.mean << " off on average";
}

} // namespace
} // namespace steerseg::test
