// The other structures in the 3D view (issue 49): two spheres of mask runs, red and blue, beside
// the level set's sphere, each pixel held against the analytic spheres the ray meets: the
// nearest one's colour where it is clear which that is, black where the ray meets none.
#include "core/mask_runs.hpp"
#include "render/renderer.hpp"
#include "render_scene.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

using render::ViewKind;

constexpr glm::ivec3 kDims{40, 40, 40};

struct Ball {
    glm::dvec3 centre;
    double radius;
};
// The camera looks from the front (-y) along +y: red lies in front of the level set's sphere,
// overlapping it on the picture, blue behind it, overlapping it too.
constexpr Ball kActive{{20.0, 26.0, 20.0}, 6.0};
constexpr Ball kRed{{14.0, 13.0, 20.0}, 5.0};
constexpr Ball kBlue{{26.0, 31.0, 21.0}, 5.0};

enum class Seen { Nothing, Active, Red, Blue, Unsure };

Geometry unitGeometry() {
    Geometry g;
    g.dims = kDims;
    return g; // 1 mm voxels, origin 0, identity direction: world == index
}

MaskRuns ballRuns(const Ball& b) {
    std::vector<std::uint8_t> mask(static_cast<std::size_t>(kDims.x) * kDims.y * kDims.z);
    for (int k = 0; k < kDims.z; ++k) {
        for (int j = 0; j < kDims.y; ++j) {
            for (int i = 0; i < kDims.x; ++i) {
                const bool inside = glm::length(glm::dvec3(i, j, k) - b.centre) <= b.radius;
                mask[linearIndex(kDims, i, j, k)] = inside ? 1 : 0;
            }
        }
    }
    return encodeRuns(mask);
}

// Where the ray from `eye` along unit `dir` enters the ball, when it surely does: its closest
// approach `margin` inside the silhouette. Unsure within `margin` of it (the voxels' surface
// lies up to about a voxel off the analytic one).
struct Entry {
    bool unsure = false;
    std::optional<double> t;
};
Entry enter(const glm::dvec3& eye, const glm::dvec3& dir, const Ball& b) {
    constexpr double kMargin = 1.5;
    const glm::dvec3 rel = b.centre - eye;
    const double along = glm::dot(rel, dir);
    const double miss = glm::length(rel - along * dir);
    if (std::abs(miss - b.radius) < kMargin) {
        return {true, std::nullopt};
    }
    if (miss > b.radius) {
        return {};
    }
    return {false, along - std::sqrt(b.radius * b.radius - miss * miss)};
}

// What the pixel's ray should show first, with the balls given (nullptr: not drawn; nor those
// whose centre lies beyond cutBeyondX); `hides` whether it hides another ball behind it.
Seen expected(const render::Camera& cam, const glm::ivec2& size, int x, int y,
              const std::array<const Ball*, 3>& balls, const std::optional<double>& cutBeyondX,
              bool& hides) {
    const glm::dvec2 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (y + 0.5) / size.y * 2.0);
    const glm::dvec3 dir = cam.rayDirection(ndc, static_cast<double>(size.x) / size.y);
    const std::array<Seen, 3> kinds{Seen::Active, Seen::Red, Seen::Blue};
    Seen best = Seen::Nothing;
    double bestT = 1e30;
    double secondT = 1e30;
    for (std::size_t n = 0; n < balls.size(); ++n) {
        if (balls[n] == nullptr || (cutBeyondX && balls[n]->centre.x > *cutBeyondX)) {
            continue;
        }
        const Entry e = enter(cam.eye(), dir, *balls[n]);
        if (e.unsure) {
            return Seen::Unsure;
        }
        if (!e.t) {
            continue;
        }
        if (*e.t < bestT) {
            secondT = bestT;
            bestT = *e.t;
            best = kinds[n];
        } else {
            secondT = std::min(secondT, *e.t);
        }
    }
    hides = secondT < 1e30;
    // Two surfaces within two voxels of each other: either may be in front.
    return hides && secondT - bestT < 2.0 ? Seen::Unsure : best;
}

Seen seen(const std::uint8_t* px) {
    const int r = px[0];
    const int g = px[1];
    const int b = px[2];
    if (isBlack(px)) {
        return Seen::Nothing;
    }
    if (r > 40 && r > 2 * g + 10 && r > 2 * b + 10) {
        return Seen::Red;
    }
    if (b > 40 && b > 2 * r + 10 && b > 2 * g + 10) {
        return Seen::Blue;
    }
    // The level set's surface: orange (0.95, 0.62, 0.25), however lit.
    if (r > 40 && 20 * g > 9 * r && 4 * b < 3 * g) {
        return Seen::Active;
    }
    return Seen::Unsure;
}

const char* name(Seen s) {
    switch (s) {
    case Seen::Nothing:
        return "nothing";
    case Seen::Active:
        return "the level set";
    case Seen::Red:
        return "red";
    case Seen::Blue:
        return "blue";
    case Seen::Unsure:
        break;
    }
    return "something else";
}

struct Tally {
    int checked = 0;
    int wrong = 0;
    std::array<int, 5> shown{}; // pixels seen as each Seen, all pixels
    std::array<int, 5> asked{}; // pixels expected as each
    int hiding = 0;             // checked pixels whose nearest ball hides another
};

// Every pixel with a sure expectation against what it shows (`activeDrawn` false: pixels where
// the level set's surface is nearest are not checked, as under a translucent surface).
Tally compare(const RgbaImage& img, const render::ViewParams& p,
              const std::array<const Ball*, 3>& balls, bool activeDrawn = true,
              const std::optional<double>& cutBeyondX = std::nullopt) {
    Tally t;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const Seen got = seen(img.at(x, y));
            ++t.shown[static_cast<std::size_t>(got)];
            bool hides = false;
            const Seen want = expected(p.camera, p.size, x, y, balls, cutBeyondX, hides);
            if (want == Seen::Unsure || (!activeDrawn && want == Seen::Active)) {
                continue;
            }
            ++t.checked;
            t.hiding += hides ? 1 : 0;
            ++t.asked[static_cast<std::size_t>(want)];
            if (got != want) {
                ++t.wrong;
                ADD_FAILURE() << "pixel " << x << "," << y << " shows " << name(got) << " ("
                              << int(img.at(x, y)[0]) << "," << int(img.at(x, y)[1]) << ","
                              << int(img.at(x, y)[2]) << "), expected " << name(want);
                if (t.wrong > 20) {
                    return t;
                }
            }
        }
    }
    return t;
}

int shown(const Tally& t, Seen s) {
    return t.shown[static_cast<std::size_t>(s)];
}
int asked(const Tally& t, Seen s) {
    return t.asked[static_cast<std::size_t>(s)];
}

class RenderStructures : public GpuTest {
  protected:
    RenderStructures()
        : scan_(makeScan(unitGeometry(), [](glm::ivec3) { return 100.0F; })), renderer_(scan_),
          pool_(spherePool(kDims, kActive.centre, kActive.radius)), red_(ballRuns(kRed)),
          blue_(ballRuns(kBlue)) {}

    // The 3D view from the front, the spheres filling most of it, with a transfer function that
    // shows nothing of the scan.
    render::ViewParams params() const {
        render::ViewParams p = renderer_.defaultParams(ViewKind::Volume3d, {128, 128});
        p.camera.zoom(1.8);
        p.transfer = {};
        return p;
    }

    RgbaImage draw(const render::ViewParams& p, bool withLevelSet = true) {
        const solver::BrickPoolView view = pool_.view();
        renderer_.render(p, withLevelSet ? &view : nullptr);
        return renderer_.readback();
    }

    void show(bool redVisible, bool blueVisible, std::uint64_t version) {
        const std::array<render::StructureSurface, 2> others{
            render::StructureSurface{&red_, {1.0F, 0.0F, 0.0F}, redVisible},
            render::StructureSurface{&blue_, {0.0F, 0.0F, 1.0F}, blueVisible}};
        renderer_.setStructures(others, version);
    }

    Volume scan_;
    render::Renderer renderer_;
    GpuPool pool_;
    MaskRuns red_;
    MaskRuns blue_;
};

TEST_F(RenderStructures, EachIsDrawnInItsColourTheNearestInFront) {
    show(true, true, 1);
    const render::ViewParams p = params();
    const Tally t = compare(draw(p), p, {&kActive, &kRed, &kBlue});
    EXPECT_EQ(t.wrong, 0);
    // The picture holds every kind, and the overlaps were checked: red over the level set's
    // sphere, the sphere over blue.
    EXPECT_GT(asked(t, Seen::Nothing), 8000);
    EXPECT_GT(asked(t, Seen::Red), 300);
    EXPECT_GT(asked(t, Seen::Blue), 40);
    EXPECT_GT(asked(t, Seen::Active), 80);
    EXPECT_GT(t.hiding, 100);
    EXPECT_GT(shown(t, Seen::Red), 1000);
    EXPECT_GT(shown(t, Seen::Blue), 300);
}

TEST_F(RenderStructures, DrawnWithoutALevelSetAndOverATranslucentOne) {
    show(true, true, 1);
    render::ViewParams p = params();
    const Tally alone = compare(draw(p, false), p, {nullptr, &kRed, &kBlue});
    EXPECT_EQ(alone.wrong, 0);
    EXPECT_GT(asked(alone, Seen::Blue), 250);
    p.surface = render::SurfaceMode::Translucent;
    const Tally translucent = compare(draw(p), p, {&kActive, &kRed, &kBlue}, false);
    EXPECT_EQ(translucent.wrong, 0);
    EXPECT_GT(asked(translucent, Seen::Red), 300);
    // Region of interest "inside": the scan outside the surface is dropped, not the others.
    p.surface = render::SurfaceMode::Opaque;
    p.roi = render::RoiMode::Inside;
    const Tally roi = compare(draw(p), p, {&kActive, &kRed, &kBlue});
    EXPECT_EQ(roi.wrong, 0);
    EXPECT_GT(asked(roi, Seen::Blue), 40);
}

TEST_F(RenderStructures, TheScanHidesThemAndTheyHideIt) {
    // An opaque grey slab (500) in front of everything, or behind everything.
    for (const bool front : {true, false}) {
        const Volume slab = makeScan(unitGeometry(), [front](glm::ivec3 v) {
            return (front ? v.y >= 2 && v.y <= 5 : v.y >= 36 && v.y <= 39) ? 500.0F : 100.0F;
        });
        render::Renderer renderer(slab);
        const std::array<render::StructureSurface, 2> others{
            render::StructureSurface{&red_, {1.0F, 0.0F, 0.0F}, true},
            render::StructureSurface{&blue_, {0.0F, 0.0F, 1.0F}, true}};
        renderer.setStructures(others, 1);
        render::ViewParams p = params();
        p.transfer.widgets.push_back({500.0, 150.0, 0.0, {0.9, 0.9, 0.9}, 1.0});
        const solver::BrickPoolView view = pool_.view();
        renderer.render(p, &view);
        const RgbaImage img = renderer.readback();
        Tally t;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                ++t.shown[static_cast<std::size_t>(seen(img.at(x, y)))];
            }
        }
        if (front) {
            EXPECT_EQ(shown(t, Seen::Red), 0);
            EXPECT_EQ(shown(t, Seen::Blue), 0);
            EXPECT_EQ(shown(t, Seen::Nothing), 0);
        } else {
            // The slab is the background now: most of what was black is grey.
            EXPECT_GT(shown(t, Seen::Red), 1000);
            EXPECT_GT(shown(t, Seen::Blue), 300);
            EXPECT_GT(shown(t, Seen::Unsure), 8000);
        }
    }
}

TEST_F(RenderStructures, SingleVoxelIsDrawnWhereverItLies) {
    // In each of seven neighbouring skipping blocks along i (2 voxels a side here), so that a
    // block the search wrongly jumps loses one.
    const render::ViewParams p = params();
    for (int i = 6; i <= 18; i += 2) {
        std::vector<std::uint8_t> mask(static_cast<std::size_t>(kDims.x) * kDims.y * kDims.z);
        mask[linearIndex(kDims, i, 12, 20)] = 1;
        const MaskRuns runs = encodeRuns(mask);
        const std::array<render::StructureSurface, 1> one{
            render::StructureSurface{&runs, {1.0F, 0.0F, 0.0F}, true}};
        renderer_.setStructures(one, static_cast<std::uint64_t>(i));
        const RgbaImage img = draw(p, false);
        int red = 0;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                red += seen(img.at(x, y)) == Seen::Red ? 1 : 0;
            }
        }
        EXPECT_GT(red, 2) << "the voxel at " << i << ",12,20";
    }
}

TEST(RenderLabelledBlocks, FlagsExactlyTheBlocksHoldingALabel) {
    const glm::ivec3 dims{13, 7, 9};
    std::vector<std::uint8_t> labels(static_cast<std::size_t>(dims.x) * dims.y * dims.z);
    // Sparse labels, only where i < 6 and k < 5: some blocks of every size hold none.
    std::uint32_t seed = 12345;
    for (int k = 0; k < 5; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < 6; ++i) {
                seed = seed * 1664525U + 1013904223U;
                labels[linearIndex(dims, i, j, k)] =
                    (seed >> 24) < 24 ? static_cast<std::uint8_t>(1 + (seed >> 16) % 3) : 0;
            }
        }
    }
    for (const int block : {2, 4, 8}) {
        const glm::ivec3 grid = (dims + block - 1) / block;
        const std::vector<std::uint8_t> blocks = render::labelledBlocks(labels, dims, block);
        ASSERT_EQ(blocks.size(), static_cast<std::size_t>(grid.x) * grid.y * grid.z);
        std::vector<std::uint8_t> want(blocks.size());
        for (int k = 0; k < dims.z; ++k) {
            for (int j = 0; j < dims.y; ++j) {
                for (int i = 0; i < dims.x; ++i) {
                    if (labels[linearIndex(dims, i, j, k)] != 0) {
                        want[linearIndex(grid, i / block, j / block, k / block)] = 1;
                    }
                }
            }
        }
        EXPECT_EQ(blocks, want) << "blocks of " << block;
        EXPECT_GT(std::count(want.begin(), want.end(), 1), 0);
        EXPECT_LT(std::count(want.begin(), want.end(), 1), static_cast<long>(want.size()));
    }
}

TEST_F(RenderStructures, HiddenOneIsNotDrawn) {
    show(true, false, 1);
    const render::ViewParams p = params();
    const Tally t = compare(draw(p), p, {&kActive, &kRed, nullptr});
    EXPECT_EQ(t.wrong, 0);
    EXPECT_EQ(shown(t, Seen::Blue), 0);
    EXPECT_GT(shown(t, Seen::Red), 1000);
}

TEST_F(RenderStructures, ClipPlaneCutsThem) {
    show(true, true, 1);
    render::ViewParams p = params();
    // x > 20 cut away, seen edge-on from the front: all of blue goes (x >= 21), red stays
    // (x <= 19).
    p.clip = {true, {1.0, 0.0, 0.0}, 20.0};
    const Tally side = compare(draw(p, false), p, {nullptr, &kRed, &kBlue}, true, 20.0);
    EXPECT_EQ(side.wrong, 0);
    EXPECT_EQ(shown(side, Seen::Blue), 0);
    EXPECT_GT(shown(side, Seen::Red), 1000);

    // y < 14 cut away: the rays enter through the plane, whose face shows red's section
    // (through its centre) tinted red over the scan, black under this window, and hides all
    // behind it.
    p.clip = {true, {0.0, -1.0, 0.0}, -kRed.centre.y};
    p.window = {10000.0, 10.0};
    const RgbaImage img = draw(p, false);
    int inside = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const glm::dvec2 ndc((x + 0.5) / p.size.x * 2.0 - 1.0,
                                 1.0 - (y + 0.5) / p.size.y * 2.0);
            const glm::dvec3 dir = p.camera.rayDirection(ndc, 1.0); // a square picture
            const glm::dvec3 eye = p.camera.eye();
            const glm::dvec3 hit = eye + (kRed.centre.y - eye.y) / dir.y * dir;
            const double r = glm::length(glm::dvec2(hit.x - kRed.centre.x, hit.z - kRed.centre.z));
            const Seen got = seen(img.at(x, y));
            EXPECT_NE(got, Seen::Blue) << "blue behind the cut face at " << x << "," << y;
            if (r < kRed.radius - 1.5) {
                ++inside;
                EXPECT_EQ(got, Seen::Red) << "red's section at " << x << "," << y;
            } else if (r > kRed.radius + 1.5) {
                EXPECT_NE(got, Seen::Red) << "red off its section at " << x << "," << y;
            }
        }
    }
    EXPECT_GT(inside, 150);
}

TEST_F(RenderStructures, UploadedOnlyWhenTheVersionChanges) {
    EXPECT_FALSE(renderer_.structuresVersion());
    EXPECT_EQ(renderer_.structureUploads(), 0U);
    show(true, true, 7);
    EXPECT_EQ(renderer_.structureUploads(), 1U);
    EXPECT_EQ(renderer_.structuresVersion(), 7U);
    // The same version, even with another list, is not looked at: the caller's version says
    // what changed.
    show(false, false, 7);
    draw(params());
    draw(params());
    EXPECT_EQ(renderer_.structureUploads(), 1U);
    EXPECT_GT(shown(compare(draw(params()), params(), {&kActive, &kRed, &kBlue}), Seen::Blue), 100);
    show(true, false, 8);
    EXPECT_EQ(renderer_.structureUploads(), 2U);
    const render::ViewParams p = params();
    EXPECT_EQ(shown(compare(draw(p), p, {&kActive, &kRed, nullptr}), Seen::Blue), 0);
}

TEST_F(RenderStructures, NoneShownDrawsTheSamePictureAsNone) {
    const render::ViewParams p = params();
    const RgbaImage before = draw(p);
    show(true, true, 1);
    const RgbaImage with = draw(p);
    EXPECT_NE(before.pixels, with.pixels);
    show(false, false, 2);
    const RgbaImage hidden = draw(p);
    EXPECT_EQ(before.pixels, hidden.pixels);
}

TEST_F(RenderStructures, RefusesMasksOfAnotherScan) {
    show(true, true, 1);
    const MaskRuns small = encodeRuns(std::vector<std::uint8_t>(64, 1));
    const std::array<render::StructureSurface, 1> wrong{
        render::StructureSurface{&small, {0.0F, 1.0F, 0.0F}, true}};
    EXPECT_THROW(renderer_.setStructures(wrong, 2), std::invalid_argument);
    const std::array<render::StructureSurface, 1> none{render::StructureSurface{}};
    EXPECT_THROW(renderer_.setStructures(none, 2), std::invalid_argument);
    // Still the structures given last.
    EXPECT_EQ(renderer_.structuresVersion(), 1U);
    const render::ViewParams p = params();
    EXPECT_EQ(compare(draw(p), p, {&kActive, &kRed, &kBlue}).wrong, 0);
}

} // namespace
} // namespace steerseg::test
