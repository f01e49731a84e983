// Patient orientation: a marker on the patient's left (or front) shows on the labelled side,
// whatever the storage order of the scan's axes.
#include "render/renderer.hpp"
#include "render/slice_frame.hpp"
#include "render_scene.hpp"
#include "support/gpu_fixture.hpp"

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

using render::ViewKind;

// A 32^3 scan, 1 mm voxels, with a bright cube around the world point `markerWorld`.
Volume markerScan(const glm::dmat3& direction, const glm::dvec3& markerWorld) {
    Geometry g;
    g.dims = {32, 32, 32};
    g.direction = direction;
    g.origin = -(direction * glm::dvec3(15.5)); // volume centred on the world origin
    const Geometry geometry = g;
    return makeScan(g, [geometry, markerWorld](glm::ivec3 v) {
        const glm::dvec3 w = geometry.indexToWorld(glm::dvec3(v));
        const glm::dvec3 d = glm::abs(w - markerWorld);
        return d.x < 4.0 && d.y < 4.0 && d.z < 4.0 ? 1000.0F : 0.0F;
    });
}

// Mean pixel x and y of bright (grey > 128) pixels, labels excluded.
glm::dvec2 brightCentroid(const RgbaImage& img) {
    glm::dvec2 sum(0.0);
    int n = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* px = img.at(x, y);
            if (px[0] > 128 && px[0] == px[1] && px[1] == px[2]) {
                sum += glm::dvec2(x, y);
                ++n;
            }
        }
    }
    EXPECT_GT(n, 20) << "marker not visible";
    return n > 0 ? sum / static_cast<double>(n) : glm::dvec2(-1.0);
}

bool orangeNear(const RgbaImage& img, int x0, int x1, int y0, int y1) {
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* px = img.at(x, y);
            if (px[0] > 200 && px[1] > 100 && px[1] < 180 && px[2] < 60) {
                return true;
            }
        }
    }
    return false;
}

struct Storage {
    const char* name;
    glm::dmat3 direction;
};
const Storage kStorages[] = {
    {"LPS", glm::dmat3(1.0)},
    {"RAS", glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1))},
    // Axes permuted: i runs inferior->superior, j left->right... (columns are axis directions)
    {"permuted", glm::dmat3(glm::dvec3(0, 0, 1), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0))},
};

class RenderOrientation : public GpuTest {};

TEST_F(RenderOrientation, LeftMarkerOnScreenRightInAxialAndCoronal) {
    for (const Storage& s : kStorages) {
        SCOPED_TRACE(s.name);
        const Volume scan = markerScan(s.direction, {10.0, 0.0, 0.0}); // patient's left
        render::Renderer renderer(scan);
        for (ViewKind kind : {ViewKind::Axial, ViewKind::Coronal}) {
            render::ViewParams p = renderer.defaultParams(kind, {64, 64});
            p.window = {500.0, 1000.0};
            const render::SliceFrame f = *renderer.render(p, nullptr);
            const RgbaImage img = renderer.readback();
            EXPECT_GT(brightCentroid(img).x, 40.0);
            EXPECT_EQ(f.labels[0], 'R');
            EXPECT_EQ(f.labels[1], 'L');
            EXPECT_EQ(f.labels[2], kind == ViewKind::Axial ? 'A' : 'S');
            EXPECT_EQ(f.labels[3], kind == ViewKind::Axial ? 'P' : 'I');
            // The letters are drawn at the edges.
            EXPECT_TRUE(orangeNear(img, 56, 64, 24, 40)) << "no label at the right edge";
            EXPECT_TRUE(orangeNear(img, 0, 8, 24, 40)) << "no label at the left edge";
        }
    }
}

TEST_F(RenderOrientation, AnteriorMarkerOnTheLeftInSagittalAndUpInAxial) {
    for (const Storage& s : kStorages) {
        SCOPED_TRACE(s.name);
        const Volume scan = markerScan(s.direction, {0.0, -10.0, 0.0}); // anterior
        render::Renderer renderer(scan);
        render::ViewParams p = renderer.defaultParams(ViewKind::Sagittal, {64, 64});
        p.window = {500.0, 1000.0};
        const render::SliceFrame f = *renderer.render(p, nullptr);
        EXPECT_LT(brightCentroid(renderer.readback()).x, 24.0);
        EXPECT_EQ(f.labels[0], 'A');
        EXPECT_EQ(f.labels[1], 'P');
        p.kind = ViewKind::Axial;
        renderer.render(p, nullptr);
        EXPECT_LT(brightCentroid(renderer.readback()).y, 24.0);
    }
}

TEST_F(RenderOrientation, AnteriorCameraShowsPatientLeftOnScreenRight) {
    for (const Storage& s : kStorages) {
        SCOPED_TRACE(s.name);
        const Volume scan = markerScan(s.direction, {10.0, 0.0, 8.0}); // left and superior
        render::Renderer renderer(scan);
        render::ViewParams p = renderer.defaultParams(ViewKind::Volume3d, {64, 64});
        p.transfer.widgets = {{1000.0, 400.0, 0.0, {1.0, 1.0, 1.0}, 1.0}};
        p.transfer.gradientScale = 1.0;
        renderer.render(p, nullptr);
        const RgbaImage img = renderer.readback();
        glm::dvec2 sum(0.0);
        int n = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                if (img.at(x, y)[0] > 40) {
                    sum += glm::dvec2(x, y);
                    ++n;
                }
            }
        }
        ASSERT_GT(n, 10);
        EXPECT_GT(sum.x / n, 36.0) << "patient's left not on the screen's right";
        EXPECT_LT(sum.y / n, 28.0) << "superior not up";
    }
}

TEST(RenderSliceFrame, RejectsSliceOutsideTheVolumeAndBadZoom) {
    Geometry g;
    g.dims = {16, 16, 8};
    render::ViewParams p;
    p.kind = ViewKind::Axial;
    p.slice = 8;
    EXPECT_THROW(render::sliceFrame(g, p), std::invalid_argument);
    p.slice = 7;
    EXPECT_NO_THROW(render::sliceFrame(g, p));
    p.zoom = 0.0;
    EXPECT_THROW(render::sliceFrame(g, p), std::invalid_argument);
    p.zoom = 1.0;
    p.kind = ViewKind::Volume3d;
    EXPECT_THROW(render::sliceFrame(g, p), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
