// The renderer's host API: GL state left as found, bad inputs refused, probe statistics,
// transfer-function baking, the skipping grid, and displaying the solver's scan texture.
#include "gpu/gl_handle.hpp"
#include "gpu/gpu_info.hpp"
#include "render/renderer.hpp"
#include "render/skip_grid.hpp"
#include "render/transfer_function.hpp"
#include "render_scene.hpp"
#include "session/probe.hpp"
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

using render::ViewKind;

Geometry cube(int n) {
    Geometry g;
    g.dims = {n, n, n};
    return g;
}

class RenderApi : public GpuTest {};

struct PictureDifference {
    int worst = 0;     // largest channel difference
    double mean = 0.0; // mean channel difference
};

PictureDifference difference(const RgbaImage& a, const RgbaImage& b) {
    PictureDifference d;
    long total = 0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        const int c = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        d.worst = std::max(d.worst, c);
        total += c;
    }
    d.mean =
        static_cast<double>(total) / static_cast<double>(std::max<std::size_t>(a.pixels.size(), 1));
    return d;
}

// The kiosk draws a slow 3D view over several frames in tiles, into a picture of its own that
// the slice views drawn in between leave alone: the tiles must add up to the picture drawn at
// once.
TEST_F(RenderApi, TilesInTheirOwnPictureAddUpToTheWholePicture) {
    const Volume scan = makeHeadScene();
    render::Renderer renderer(scan);
    GpuPool pool(spherePool(scan.dims(), kHeadLesionCentre, kHeadLesionRadius));
    const BrickPoolView view = pool.view();
    for (ViewKind kind : {ViewKind::Volume3d, ViewKind::Coronal}) {
        render::ViewParams whole = renderer.defaultParams(kind, {48, 37});
        renderer.render(whole, &view);
        const RgbaImage expected = renderer.readback();

        render::ViewParams band = whole;
        band.target = 3;
        for (int y = 0; y < 37; y += 11) {
            for (int x = 0; x < 48; x += 16) {
                band.region = {x, y, 16, 11};
                renderer.render(band, &view);
            }
            // A slice view into another picture between bands must not disturb this one.
            render::ViewParams other = renderer.defaultParams(ViewKind::Axial, {20, 20});
            other.target = 1;
            renderer.render(other, &view);
        }
        EXPECT_EQ(renderer.target(3).readback().pixels, expected.pixels);
    }
    render::ViewParams bad = renderer.defaultParams(ViewKind::Axial, {8, 8});
    bad.target = render::kRenderTargets;
    EXPECT_THROW(renderer.render(bad, nullptr), std::invalid_argument);
}

TEST_F(RenderApi, RestoresTheGlStateItChanges) {
    const Volume scan = makeHeadScene();
    render::Renderer renderer(scan);
    gpu::Texture tex2d = gpu::createTexture();
    gpu::Texture tex3d = gpu::createTexture();
    gpu::Buffer ssbo = gpu::createBuffer(GL_SHADER_STORAGE_BUFFER, 64, nullptr, GL_STATIC_DRAW);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex2d.id());
    glBindTexture(GL_TEXTURE_3D, tex3d.id());
    glActiveTexture(GL_TEXTURE2);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, ssbo.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    GpuPool pool(spherePool(scan.dims(), kHeadLesionCentre, kHeadLesionRadius));
    const BrickPoolView view = pool.view();
    for (ViewKind kind : {ViewKind::Volume3d, ViewKind::Axial}) {
        renderer.render(renderer.defaultParams(kind, {32, 32}), &view);
        (void)renderer.readback();
        GLint value = 0;
        glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
        EXPECT_EQ(value, GL_TEXTURE2);
        glGetIntegerv(GL_CURRENT_PROGRAM, &value);
        EXPECT_EQ(value, 0);
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 1, &value);
        EXPECT_EQ(static_cast<GLuint>(value), ssbo.id());
        glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &value);
        EXPECT_EQ(value, 0);
        glGetIntegerv(GL_PACK_ALIGNMENT, &value);
        EXPECT_EQ(value, 8);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &value);
        EXPECT_EQ(static_cast<GLuint>(value), tex2d.id());
        glGetIntegerv(GL_TEXTURE_BINDING_3D, &value);
        EXPECT_EQ(static_cast<GLuint>(value), tex3d.id());
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &value);
        EXPECT_EQ(value, 0);
        glActiveTexture(GL_TEXTURE2);
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glActiveTexture(GL_TEXTURE0);
}

// With float linear filtering the solver and the renderer share one R32F texture (the scan on
// the GPU once); the pictures match those from the R16F copy that drivers without float
// filtering display, up to half-float rounding.
TEST_F(RenderApi, DisplaysTheSharedScanTextureLikeTheHalfFloatCopy) {
    const Volume scan = makeHeadScene();
    const gpu::ScanTexture texture(scan);
    const gpu::ScanTexture half(scan, gpu::ScanDisplay::HalfFloatCopy);
    LevelSetSolver solver(texture);
    render::Renderer shared(scan, solver.scan());
    render::Renderer own(scan, half);
    EXPECT_EQ(&shared.scan(), &texture);
    EXPECT_FALSE(half.displaysExact());
    EXPECT_EQ(texture.displaysExact(), gpu::queryGpuInfo().floatLinearFiltering);
    if (texture.displaysExact()) {
        EXPECT_EQ(texture.display(), texture.exact());
    }
    const Volume other = makeScan(cube(16), [](glm::ivec3) { return 1.0F; });
    EXPECT_THROW(render::Renderer(other, texture), std::invalid_argument);
    for (ViewKind kind : {ViewKind::Volume3d, ViewKind::Axial}) {
        const render::ViewParams params = own.defaultParams(kind, {64, 64});
        own.render(params, nullptr);
        shared.render(params, nullptr);
        const RgbaImage a = own.readback();
        const RgbaImage b = shared.readback();
        ASSERT_EQ(a.pixels.size(), b.pixels.size());
        const PictureDifference d = difference(a, b);
        EXPECT_LE(d.worst, 8) << static_cast<int>(kind);
        EXPECT_LT(d.mean, 0.5);
    }
}

// The gradient texture is a speed-up, not another picture: the ray caster that differences the
// scan per sample (a scan over the texture's budget) draws the same views, with and without a
// surface, opaque (found before the scan's march) and translucent, and as region of interest.
TEST_F(RenderApi, GradientTextureDrawsWhatPerSampleDifferencesDraw) {
    // Noise makes the gradient matter everywhere, not only at the scene's edges.
    const Volume head = makeHeadScene();
    const Volume scan = makeScan(head.geometry(), [&head](glm::ivec3 v) {
        const std::uint32_t h = (static_cast<std::uint32_t>(v.x) * 73856093U) ^
                                (static_cast<std::uint32_t>(v.y) * 19349663U) ^
                                (static_cast<std::uint32_t>(v.z) * 83492791U);
        return static_cast<float>(head.valueAt(v.x, v.y, v.z)) + static_cast<float>(h % 61U) -
               30.0F;
    });
    render::Renderer fast(scan);
    render::Renderer differencing(scan, 0);
    // Half floats: a budget for 8 bytes a voxel, not the 16 of full floats.
    const std::size_t voxels = static_cast<std::size_t>(scan.dims().x) * scan.dims().y *
                               static_cast<std::size_t>(scan.dims().z);
    render::Renderer half(scan, voxels * 8);
    ASSERT_TRUE(fast.precomputedGradient());
    ASSERT_TRUE(half.precomputedGradient());
    ASSERT_FALSE(differencing.precomputedGradient());
    GpuPool pool(spherePool(scan.dims(), kHeadLesionCentre, kHeadLesionRadius));
    const BrickPoolView view = pool.view();
    struct Case {
        const BrickPoolView* pool;
        render::SurfaceMode surface;
        render::RoiMode roi;
    };
    for (const Case c : {Case{nullptr, render::SurfaceMode::Opaque, render::RoiMode::Off},
                         Case{&view, render::SurfaceMode::Opaque, render::RoiMode::Off},
                         Case{&view, render::SurfaceMode::Translucent, render::RoiMode::Off},
                         Case{&view, render::SurfaceMode::Hidden, render::RoiMode::Dim}}) {
        render::ViewParams params = fast.defaultParams(ViewKind::Volume3d, {64, 64});
        params.camera.orbit(30.0, 20.0);
        params.surface = c.surface;
        params.roi = c.roi;
        fast.render(params, c.pool);
        differencing.render(params, c.pool);
        half.render(params, c.pool);
        const RgbaImage reference = differencing.readback();
        for (const RgbaImage& picture : {fast.readback(), half.readback()}) {
            const PictureDifference d = difference(picture, reference);
            EXPECT_LE(d.worst, 24) << "surface " << static_cast<int>(c.surface);
            EXPECT_LT(d.mean, 0.5)
                << "surface " << static_cast<int>(c.surface) << " roi " << static_cast<int>(c.roi);
        }
    }
}

TEST_F(RenderApi, RefusesAPoolOfOtherDimensionsAndBadSizes) {
    const Volume scan = makeScan(cube(16), [](glm::ivec3) { return 1.0F; });
    render::Renderer renderer(scan);
    GpuPool pool(spherePool({16, 16, 12}, glm::dvec3(8.0), 4.0));
    const BrickPoolView view = pool.view();
    EXPECT_THROW(renderer.render(renderer.defaultParams(ViewKind::Axial, {16, 16}), &view),
                 std::invalid_argument);
    EXPECT_THROW(renderer.render(renderer.defaultParams(ViewKind::Axial, {0, 16}), nullptr),
                 std::invalid_argument);
}

TEST(RenderSkipGrid, EachBlockHoldsTheCellsItsSamplesLieIn) {
    const glm::ivec3 dims{20, 9, 9};
    std::vector<float> values(static_cast<std::size_t>(dims.x * dims.y * dims.z), 0.0F);
    values[8] = 1.0F; // voxel (8, 0, 0): first voxel of block 1, a corner of block 0's last cell
    const std::vector<float> bands = render::blockBands(values, dims, 8);
    const std::size_t per = render::kSkipBands;
    ASSERT_EQ(bands.size(), 3u * 2u * 2u * per);
    const auto band = [&](int block, int b) {
        return bands[per * static_cast<std::size_t>(block) + static_cast<std::size_t>(b)];
    };
    // Block (0,0,0)'s samples reach x 7.5: cell 7 (corners 7 and 8) spans 0..1, every band.
    // Its largest gradient, at voxel (8,0,0) itself with the edge clamped: (0, -3, -3) / 8 (the
    // edge voxel stands for rows -1 and -2: 2 x (0 - 1) + (0 - 1)).
    for (int b = 0; b < render::kSkipBands; ++b) {
        EXPECT_FLOAT_EQ(band(0, b), 3.0F / 8.0F * std::sqrt(2.0F)) << b;
        EXPECT_FLOAT_EQ(band(1, b), 3.0F / 8.0F * std::sqrt(2.0F)) << b;
    }
    // Block (2,0,0) starts at cell 15: no bright corner, no gradient (voxel 8 is 7 away).
    EXPECT_EQ(band(2, 0), 0.0F);
    EXPECT_EQ(band(2, render::kSkipBands - 1), -1.0F);
    // Block (0,1,0) (samples from j 7.5): cells from j 7, seven rows from voxel (8,0,0):
    // neither its intensity nor its gradient (two rows either side) reaches them.
    EXPECT_EQ(band(3, 0), 0.0F);
    EXPECT_EQ(band(3, render::kSkipBands - 1), -1.0F);
}

// The skipping is conservative: every sample the ray caster could take, anywhere in a block,
// with an occupied transfer-function texel under its (intensity, gradient) lookup lies in a
// block visibleBlocks keeps. Samples at random on noise with steps, all three block sizes.
TEST(RenderSkipGrid, NoVisibleSampleLiesInASkippedBlock) {
    const glm::ivec3 dims{19, 14, 11};
    std::vector<float> values(static_cast<std::size_t>(dims.x * dims.y * dims.z));
    std::uint32_t seed = 12345U;
    const auto next = [&seed] {
        seed = seed * 1664525U + 1013904223U;
        return static_cast<float>(seed >> 8) / 16777216.0F;
    };
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const float base = i < 9 ? 0.1F : (j < 7 ? 0.45F : 0.8F);
                values[linearIndex(dims, i, j, k)] = base + 0.04F * (next() - 0.5F);
            }
        }
    }
    const auto at = [&](glm::ivec3 v) {
        v = glm::clamp(v, glm::ivec3(0), dims - 1);
        return values[linearIndex(dims, v.x, v.y, v.z)];
    };
    const auto gradientAt = [&](glm::ivec3 v) {
        glm::vec3 g;
        for (int a = 0; a < 3; ++a) {
            glm::ivec3 e(0);
            e[a] = 1;
            g[a] = (2.0F * (at(v + e) - at(v - e)) + at(v + 2 * e) - at(v - 2 * e)) / 8.0F;
        }
        return g;
    };
    render::TransferFunction tf; // gradient-gated: the noise alone stays below the ramp
    tf.gradientScale = 0.15;
    tf.widgets.push_back({0.45, 0.2, 0.3, {1.0, 1.0, 1.0}, 0.5});
    const std::vector<std::uint8_t> lut = render::bakeTransferLut(tf, 0.0, 1.0);
    const std::vector<float> table = render::occupancyTable(lut);
    const auto occupied = [&](int bin, int grad) {
        return lut[4 * (static_cast<std::size_t>(grad) * render::kTfIntensityBins +
                        static_cast<std::size_t>(bin)) +
                   3] != 0;
    };
    for (const int block : {2, 4, 8}) {
        const std::vector<float> bands = render::blockBands(values, dims, block);
        const glm::ivec3 grid = (dims + block - 1) / block;
        int skipped = 0;
        int visibleSamples = 0;
        for (std::size_t b = 0; b < bands.size() / render::kSkipBands; ++b) {
            skipped += render::bandsVisible(&bands[b * render::kSkipBands], table, tf.gradientScale)
                           ? 0
                           : 1;
        }
        for (int n = 0; n < 20000; ++n) {
            const glm::vec3 p = glm::vec3(next(), next(), next()) * glm::vec3(dims) - 0.5F;
            const glm::ivec3 c = glm::ivec3(glm::floor(p));
            const glm::vec3 f = p - glm::vec3(c);
            float v = 0.0F;
            glm::vec3 g(0.0F);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::ivec3 o(corner & 1, (corner >> 1) & 1, corner >> 2);
                const glm::vec3 w = glm::mix(1.0F - f, f, glm::vec3(o));
                v += w.x * w.y * w.z * at(c + o);
                g += w.x * w.y * w.z * gradientAt(glm::clamp(c + o, glm::ivec3(0), dims - 1));
            }
            const float bin = v * (render::kTfIntensityBins - 1);
            const float gm = std::min(glm::length(g) / static_cast<float>(tf.gradientScale), 1.0F) *
                             (render::kTfGradientBins - 1);
            bool visible = false;
            for (const int b :
                 {static_cast<int>(std::floor(bin)), static_cast<int>(std::ceil(bin))}) {
                for (const int gb :
                     {static_cast<int>(std::floor(gm)), static_cast<int>(std::ceil(gm))}) {
                    visible =
                        visible || occupied(std::clamp(b, 0, render::kTfIntensityBins - 1), gb);
                }
            }
            if (!visible) {
                continue;
            }
            ++visibleSamples;
            const glm::ivec3 at3 =
                glm::clamp(glm::ivec3(glm::floor((p + 0.5F) / static_cast<float>(block))),
                           glm::ivec3(0), grid - 1);
            const std::size_t cell =
                static_cast<std::size_t>(at3.x + grid.x * (at3.y + grid.y * at3.z));
            EXPECT_TRUE(
                render::bandsVisible(&bands[cell * render::kSkipBands], table, tf.gradientScale))
                << "block size " << block << " sample " << p.x << "," << p.y << "," << p.z;
        }
        // The test means something: visible samples exist, and blocks are skipped.
        EXPECT_GT(visibleSamples, 100) << block;
        EXPECT_GT(skipped, 0) << block;
    }
}

TEST(RenderTransfer, BakesTentTimesGradientRampAndMarksOccupiedBins) {
    render::TransferFunction tf;
    tf.widgets.push_back({50.0, 10.0, 0.5, {1.0, 0.0, 0.0}, 1.0});
    const std::vector<std::uint8_t> lut = render::bakeTransferLut(tf, 0.0, 255.0);
    auto alpha = [&](int bin, int grad) {
        return lut[4 * (static_cast<std::size_t>(grad) * render::kTfIntensityBins +
                        static_cast<std::size_t>(bin)) +
                   3];
    };
    EXPECT_EQ(alpha(50, render::kTfGradientBins - 1), 255);
    EXPECT_EQ(alpha(50, 0), 0);                                    // below the gradient threshold
    EXPECT_EQ(alpha(100, 31), 0);                                  // outside the tent
    EXPECT_EQ(lut[4 * (31 * render::kTfIntensityBins + 50)], 255); // red
    const std::vector<float> table = render::occupancyTable(lut);
    const int top = render::kTfGradientBins - 1;
    EXPECT_TRUE(render::occupiedIn(table, 50, 50, top));
    EXPECT_TRUE(render::occupiedIn(table, 0, 255, top));
    EXPECT_FALSE(render::occupiedIn(table, 30, 30, top));
    EXPECT_FALSE(render::occupiedIn(table, 70, 70, top));
    EXPECT_FALSE(render::occupiedIn(table, 0, 255, 10)); // homogeneous: below the ramp
    EXPECT_TRUE(render::occupiedIn(table, 45, 55, 20));
}

TEST(RenderProbe, MeanAndStddevInASphere) {
    Geometry g = cube(9);
    g.spacing = {1.0, 1.0, 2.0};
    Volume v(VoxelType::Float32, g);
    auto out = v.voxels<float>();
    for (int k = 0; k < 9; ++k) {
        for (int j = 0; j < 9; ++j) {
            for (int i = 0; i < 9; ++i) {
                out[v.linearIndex(i, j, k)] = (i % 2 == 0) ? 300.0F : 100.0F;
            }
        }
    }
    // Radius 1 mm around (4,4,4): the centre and its four +-i/+-j neighbours (k is 2 mm away).
    const session::ProbeStats s = session::probe(v, {4.0, 4.0, 4.0}, 1.0);
    EXPECT_EQ(s.count, 5u);
    EXPECT_DOUBLE_EQ(s.mean, (3 * 300.0 + 2 * 100.0) / 5.0);
    const double var = (3 * 300.0 * 300.0 + 2 * 100.0 * 100.0) / 5.0 - s.mean * s.mean;
    EXPECT_NEAR(s.stddev, std::sqrt(var), 1e-9);
    const session::SuggestedSpeed speed = session::suggestSpeed(s, 2.0);
    EXPECT_DOUBLE_EQ(speed.T, s.mean);
    EXPECT_DOUBLE_EQ(speed.eps, 2.0 * s.stddev);
    EXPECT_EQ(session::probe(v, {-50.0, 0.0, 0.0}, 2.0).count, 0u);
    EXPECT_THROW(session::probe(v, {4.0, 4.0, NAN}, 1.0), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
