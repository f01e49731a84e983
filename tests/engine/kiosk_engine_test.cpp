// The kiosk's engine on the real session: scans read off the calling thread, sphere edits,
// steps, undo snapshots (GPU copies within a budget, masks beyond), export; and the screen
// compositor's placement and rotation.
#include "core/mask_depth.hpp"
#include "core/sample_phantom.hpp"
#include "core/volume.hpp"
#include "engine/session_engine.hpp"
#include "kiosk/screen_compositor.hpp"
#include "model/speed_kind.hpp"
#include "scan/scan_reader.hpp"
#include "support/gpu_fixture.hpp"
#include "support/two_textures.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace steerseg::test {
namespace {

using engine::SessionEngine;
using workflow::LoadPoll;

LoadPoll waitForLoad(SessionEngine& engine) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    for (;;) {
        LoadPoll poll = engine.pollLoad();
        if (poll.kind != LoadPoll::Running || std::chrono::steady_clock::now() > deadline) {
            return poll;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

// The built-in sample, read off the calling thread as the kiosk reads it.
bool loadsSample(SessionEngine& engine) {
    engine.beginLoad("builtin:sample");
    return waitForLoad(engine).kind == LoadPoll::Ready;
}

class KioskEngine : public GpuTest {};

// The edge speed takes its smoothing and kappa from the last probe's noise, as segment --probe.
TEST_F(KioskEngine, TheEdgeSpeedNeedsAProbeAndFollowsItsNoise) {
    SessionEngine engine(model::SolverOptions{}, {2, 3.0, 1.0});
    ASSERT_TRUE(loadsSample(engine));
    workflow::SpeedChoice edge;
    edge.kind = model::SpeedKind::Edge;
    try {
        engine.setSpeed(edge);
        FAIL() << "the edge speed was accepted before a probe";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("needs a probe first"), std::string::npos) << e.what();
    }
    const glm::dvec3 lesion{80.0, 56.0, 52.0};
    ASSERT_GT(engine.probe(lesion, 4.0).count, 0U);
    engine.setSpeed(edge);
    const session::Session& s = *engine.session();
    EXPECT_EQ(s.speed().kind, model::SpeedKind::Edge);
    EXPECT_EQ(s.speed().smoothing.iterations, 2);
    EXPECT_GT(s.speed().kappa, 0.0F);
    EXPECT_FLOAT_EQ(s.speed().smoothing.conductance, 3.0F * s.speed().kappa);
    engine.setSpeed(workflow::SpeedChoice{});
    EXPECT_EQ(s.speed().kind, model::SpeedKind::Threshold);
}

// With classify the solver evaluates the speed where the front goes; the speed view's texture
// is filled ahead of it in pieces that follow the time given, until it is whole.
TEST_F(KioskEngine, FillsTheClassifySpeedAheadInPieces) {
    const auto dir = std::filesystem::path(::testing::TempDir()) / "kiosk_fill_ahead";
    std::filesystem::create_directories(dir);
    const auto scan = dir / "two_textures.nrrd";
    {
        // 32x32x24 floats: the calm texture for i < 16, the rough one beyond.
        const std::vector<float> v = twoTextureIntensities({32, 32, 24}, 16, 99U);
        std::ofstream out(scan, std::ios::binary);
        out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 32 32 24\nendian: little\n"
               "encoding: raw\n\n";
        out.write(reinterpret_cast<const char*>(v.data()),
                  static_cast<std::streamsize>(v.size() * sizeof(float)));
    }
    SessionEngine engine(model::SolverOptions{}, {2, 3.0, 1.0});
    engine.beginLoad(scan.string());
    ASSERT_EQ(waitForLoad(engine).kind, LoadPoll::Ready);
    EXPECT_FALSE(engine.fillSpeedAhead(0.01)); // the threshold speed is whole from the start

    workflow::SpeedChoice classify;
    classify.kind = model::SpeedKind::Classify;
    classify.inside = {{{6.0F, 16.0F, 12.0F}, 4.0F}};
    classify.outside = {{{26.0F, 16.0F, 12.0F}, 4.0F}};
    engine.setSpeed(classify);
    EXPECT_EQ(engine.session()->speedBricksEvaluated(), 0U);
    const std::uint64_t before = engine.speedVersion();
    int pieces = 0;
    while (engine.fillSpeedAhead(0.002) && pieces < 1000) {
        ++pieces;
    }
    EXPECT_GT(pieces, 1); // 48 bricks, each a few milliseconds on llvmpipe, far less on a GPU
    EXPECT_LT(pieces, 1000);
    EXPECT_EQ(engine.speedVersion(), before + static_cast<std::uint64_t>(pieces));
    const model::SolverStats stats = engine.stats();
    EXPECT_EQ(engine.session()->speedBricksEvaluated(), stats.totalBricks);
    EXPECT_FALSE(engine.fillSpeedAhead(0.01));
}

TEST_F(KioskEngine, TheVolumeWhileTheFrontMovesFollowsTheStepsCounts) {
    SessionEngine engine;
    ASSERT_TRUE(loadsSample(engine));
    const PhantomLesion lesion = kPhantomLesion;
    const glm::vec3 centre(lesion.i, lesion.j, lesion.k);
    engine.addSeed({centre, 3.0F});
    engine.setParams({static_cast<float>(lesion.intensity), 190.0F, 0.8F});
    const double seeded = engine.volumeMl(); // the exact count the running one starts from
    const int interval = engine.session()->options().checkInterval;
    double last = seeded;
    for (int n = 0; n < 6; ++n) {
        // Whole check intervals: the steps' counts are all in (SolverStats::netGained).
        engine.step(4 * interval);
        const double running = engine.volumeMl();
        const double exact = engine.exactVolumeMl();
        EXPECT_NEAR(running, exact, 1e-9) << "after " << (n + 1) * 4 * interval << " iterations";
        // exactVolumeMl recounted: the next running figure starts from this count.
        EXPECT_GE(exact, last);
        last = exact;
    }
    EXPECT_GT(last, 4.0 * seeded); // the front grew: the counts had something to follow
    // An edit's voxels are counted as the GPU paints them: the figure after it is exact at once,
    // with no count of the pool (a read of every brick).
    const double countingSeconds = engine.workSeconds().count;
    engine.erase({centre, 4.0F});
    engine.addSeed({centre + glm::vec3(8.0F, 0.0F, 0.0F), 2.0F});
    const double afterEdits = engine.exactVolumeMl();
    EXPECT_EQ(engine.workSeconds().count, countingSeconds);
    EXPECT_LT(afterEdits, last);
    const glm::dvec3 s = engine.session()->scan().geometry().spacing;
    const double counted =
        static_cast<double>(engine.session()->insideVoxels()) * s.x * s.y * s.z / 1000.0;
    EXPECT_NEAR(afterEdits, counted, 1e-9);
}

// A level set seeded once stays on the GPU when nothing is left inside it; the engine then says
// it has none (what the workflow reads as "vanished"), after an erase at once and after a run
// that shrank away once its stop was counted.
TEST_F(KioskEngine, HasNoLevelSetOnceNothingIsLeftInside) {
    SessionEngine engine;
    ASSERT_TRUE(loadsSample(engine));
    const PhantomLesion lesion = kPhantomLesion;
    const glm::vec3 centre(lesion.i, lesion.j, lesion.k);
    engine.setParams({static_cast<float>(lesion.intensity), 190.0F, 0.8F});
    engine.addSeed({centre, 3.0F});
    ASSERT_GT(engine.exactVolumeMl(), 0.0);
    EXPECT_TRUE(engine.hasLevelSet());
    engine.erase({centre, 6.0F});
    EXPECT_FALSE(engine.hasLevelSet()) << "the erase took every voxel";
    engine.addSeed({centre, 3.0F});
    EXPECT_TRUE(engine.hasLevelSet());

    // A seed in the background, far from the lesion's T, shrinks away (as in SolverCli's
    // vanished run): unknown while it runs, counted at its stop.
    engine.clearLevelSet();
    engine.setParams({static_cast<float>(lesion.intensity), 20.0F, 0.5F});
    engine.addSeed({glm::vec3(60.0F, 30.0F, 40.0F), 2.0F});
    model::StepResult r;
    for (int n = 0; n < 50 && !r.converged; ++n) {
        r = engine.step(40);
    }
    ASSERT_TRUE(r.converged);
    EXPECT_EQ(engine.exactVolumeMl(), 0.0);
    EXPECT_FALSE(engine.hasLevelSet());
}

// An erase's run's limit (model::WithdrawLimit) on the real session: where the speed takes the
// whole surface back, the voxels deeper than the depth stay, but not within the sphere, where
// the surface withdraws as the speed says; lifted, the surface withdraws on.
TEST_F(KioskEngine, AWithdrawLimitKeepsTheSurfacesDeepVoxelsBeyondItsSphere) {
    SessionEngine engine;
    ASSERT_TRUE(loadsSample(engine));
    const PhantomLesion lesion = kPhantomLesion;
    const glm::vec3 centre(lesion.i, lesion.j, lesion.k);
    engine.addSeed({centre, 8.0F});
    const session::Session& s = *engine.session();
    const glm::ivec3 dims = s.scan().dims();
    const std::vector<std::uint8_t> before = s.mask();
    const double depthMm = 2.0 * s.scan().geometry().spacing.x;
    const std::vector<std::uint8_t> deep =
        deeperThan(dims, s.scan().geometry().spacing, before, depthMm);
    const model::Sphere around{centre + glm::vec3(6.0F, 0.0F, 0.0F), 3.0F};
    engine.limitWithdrawal(model::WithdrawLimit{around, depthMm});
    // A window far above every value of the scan: the speed takes back every voxel.
    engine.setParams({static_cast<float>(lesion.intensity) + 1e4F, 10.0F, 0.8F});
    engine.step(300);
    const std::vector<std::uint8_t> held = s.mask();
    const glm::vec3 scale = model::sphereScale(s.scan().geometry().spacing);
    std::size_t deepKept = 0;
    std::size_t deepLost = 0;
    std::size_t aroundHeld = 0;
    std::size_t shallowHeld = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t v = linearIndex(dims, i, j, k);
                if (model::sphereHolds(around, glm::dvec3(i, j, k), scale)) {
                    aroundHeld += held[v] != 0 ? 1 : 0;
                } else if (deep[v] != 0) {
                    (held[v] != 0 ? deepKept : deepLost) += 1;
                } else {
                    shallowHeld += held[v] != 0 ? 1 : 0;
                }
            }
        }
    }
    EXPECT_GT(deepKept, 0U);
    EXPECT_EQ(deepLost, 0U);
    EXPECT_EQ(aroundHeld, 0U) << "within the sphere the surface withdraws";
    // The surface rests against the kept voxels: of the rim only what its smoothing holds.
    EXPECT_LT(shallowHeld, deepKept / 4) << shallowHeld << " of the rim held, " << deepKept;

    engine.limitWithdrawal(std::nullopt);
    engine.step(300);
    EXPECT_EQ(s.insideVoxels(), 0U) << "lifted, the surface withdraws on";
    EXPECT_THROW(engine.limitWithdrawal(model::WithdrawLimit{around, -1.0}), std::invalid_argument);
}

TEST_F(KioskEngine, LoadsSeedsStepsUndoesAndExports) {
    SessionEngine engine;
    ASSERT_TRUE(loadsSample(engine));
    const workflow::ScanInfo info = engine.scanInfo();
    EXPECT_EQ(info.name, "sample");
    EXPECT_EQ(info.dims, makeSamplePhantom().dims());
    EXPECT_LT(info.minValue, info.maxValue);
    EXPECT_FALSE(engine.hasLevelSet());

    const glm::vec3 centre = glm::vec3(info.dims) * 0.5F;
    const workflow::ProbeResult probe = engine.probe(glm::dvec3(centre), 4.0);
    EXPECT_GT(probe.count, 0U);

    const workflow::SnapshotId empty = engine.snapshot();
    engine.addSeed({centre, 4.0F});
    EXPECT_TRUE(engine.hasLevelSet());
    const double seeded = engine.volumeMl();
    EXPECT_GT(seeded, 0.0);
    const workflow::SnapshotId oneSeed = engine.snapshot();
    engine.setParams(
        {static_cast<float>(probe.mean), static_cast<float>(3.0 * probe.stddev + 1.0), 1.0F});
    const std::uint64_t before = engine.levelSetVersion();
    const model::StepResult r = engine.step(20);
    EXPECT_EQ(r.iterations, 20);
    EXPECT_GT(engine.levelSetVersion(), before);

    engine.restore(oneSeed);
    EXPECT_NEAR(engine.volumeMl(), seeded, seeded * 0.05);
    engine.restore(empty);
    EXPECT_FALSE(engine.hasLevelSet());
    EXPECT_EQ(engine.volumeMl(), 0.0);
    engine.restore(oneSeed);
    EXPECT_TRUE(engine.hasLevelSet());
    engine.drop(oneSeed);
    EXPECT_THROW(engine.restore(oneSeed), std::logic_error);

    const auto dir = std::filesystem::temp_directory_path() / "steerseg_kiosk_engine";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    engine.exportMask(dir / "mask.nii.gz");
    const scan::LoadedScan mask = scan::readScan(dir / "mask.nii.gz");
    EXPECT_EQ(mask.volume.dims(), info.dims);
    EXPECT_THROW(engine.exportMask(dir / "missing" / "folder" / "mask.nii.gz"), std::exception);
    // Every other format the config may enable goes by the name's extension; DICOM SEG is
    // refused with one line until its writer is wired.
    for (const char* name : {"mask.seg.nrrd", "mask.stl", "mask.ply", "mask.tif"}) {
        engine.exportMask(dir / name);
        EXPECT_GT(std::filesystem::file_size(dir / name), 100u) << name;
    }
    EXPECT_EQ(scan::readScan(dir / "mask.seg.nrrd").volume.dims(), info.dims);
    EXPECT_THROW(engine.exportMask(dir / "mask.dcm"), files::WriteError);
    EXPECT_THROW(engine.exportMask(dir / "mask.obj"), files::WriteError);
    std::filesystem::remove_all(dir);
}

// Undo's copies live in GPU memory up to the engine's budget; beyond it the oldest become masks
// in host memory. A copy restores the very phi it copied, after a run too; a mask its voxels.
TEST_F(KioskEngine, UndoCopiesStayWithinTheirGpuBudgetAndRestoreWhatTheyTook) {
    const auto seeded = [](SessionEngine& engine) {
        ASSERT_TRUE(loadsSample(engine));
        const glm::vec3 centre = glm::vec3(engine.scanInfo().dims) * 0.5F;
        const workflow::ProbeResult probe = engine.probe(glm::dvec3(centre), 4.0);
        engine.addSeed({centre, 4.0F});
        engine.setParams(
            {static_cast<float>(probe.mean), static_cast<float>(3.0 * probe.stddev + 1.0), 1.0F});
        engine.step(10);
    };
    SessionEngine roomy;
    seeded(roomy);
    const std::vector<float> phi = roomy.session()->phi();
    const workflow::SnapshotId first = roomy.snapshot();
    const std::size_t oneCopy = roomy.undoGpuBytes();
    EXPECT_GT(oneCopy, 0U);
    roomy.step(20);
    const std::vector<float> later = roomy.session()->phi();
    const workflow::SnapshotId second = roomy.snapshot();
    roomy.step(20);
    EXPECT_EQ(roomy.undoMasks(), 0U);
    roomy.restore(first);
    EXPECT_EQ(roomy.session()->phi(), phi);
    roomy.restore(second);
    EXPECT_EQ(roomy.session()->phi(), later);
    roomy.drop(first);
    roomy.drop(second);
    EXPECT_EQ(roomy.undoGpuBytes(), 0U);

    // Room for one copy: the older one moves to host memory, once the frame after the edit
    // asks (keepUndoWithinBudget); until then an edit's two copies may stand above the budget.
    SessionEngine tight(model::SolverOptions{}, {}, oneCopy + oneCopy / 2);
    seeded(tight);
    const std::vector<std::uint8_t> mask = tight.session()->mask();
    const workflow::SnapshotId older = tight.snapshot();
    tight.step(20);
    const std::vector<float> newerPhi = tight.session()->phi();
    const workflow::SnapshotId newer = tight.snapshot();
    EXPECT_GT(tight.undoGpuBytes(), oneCopy + oneCopy / 2);
    EXPECT_EQ(tight.undoMasks(), 0U);
    tight.keepUndoWithinBudget();
    EXPECT_LE(tight.undoGpuBytes(), oneCopy + oneCopy / 2);
    EXPECT_EQ(tight.undoMasks(), 1U);
    tight.step(20);
    tight.restore(older);
    EXPECT_EQ(tight.session()->mask(), mask);
    tight.restore(newer);
    EXPECT_EQ(tight.session()->phi(), newerPhi);
    tight.drop(newer);
    EXPECT_EQ(tight.undoGpuBytes(), 0U);
    EXPECT_EQ(tight.undoMasks(), 1U);

    // A third copy with no frame since the last two: it moves the older ones out itself, so
    // no more than an edit's two ever stand above the budget.
    const workflow::SnapshotId third = tight.snapshot();
    const workflow::SnapshotId fourth = tight.snapshot();
    const workflow::SnapshotId fifth = tight.snapshot();
    EXPECT_LE(tight.undoGpuBytes(), 2 * oneCopy);
    EXPECT_EQ(tight.undoMasks(), 3U);
    for (const workflow::SnapshotId id : {third, fourth, fifth}) {
        tight.drop(id);
    }

    // No room at all: every snapshot is a mask, and still restores.
    SessionEngine none(model::SolverOptions{}, {}, 0);
    seeded(none);
    const std::vector<std::uint8_t> noneMask = none.session()->mask();
    const workflow::SnapshotId only = none.snapshot();
    EXPECT_EQ(none.undoGpuBytes(), 0U);
    EXPECT_EQ(none.undoMasks(), 1U);
    none.step(20);
    none.restore(only);
    EXPECT_EQ(none.session()->mask(), noneMask);
}

TEST_F(KioskEngine, AFailedLoadSaysWhyAndKeepsTheScanItHad) {
    SessionEngine engine;
    EXPECT_EQ(engine.pollLoad().kind, LoadPoll::Failed); // nothing asked for
    ASSERT_TRUE(loadsSample(engine));
    engine.beginLoad("/nonexistent/scan.nii.gz");
    const LoadPoll failed = waitForLoad(engine);
    ASSERT_EQ(failed.kind, LoadPoll::Failed);
    EXPECT_NE(failed.error.find("/nonexistent/scan.nii.gz"), std::string::npos) << failed.error;
    EXPECT_NE(engine.session(), nullptr);
    EXPECT_EQ(engine.scanInfo().name, "sample");
    // A truncated file is the reader's message, not a crash.
    const auto path = std::filesystem::temp_directory_path() / "steerseg_truncated.nii";
    std::ofstream(path) << "not a nifti";
    engine.beginLoad(path.string());
    EXPECT_EQ(waitForLoad(engine).kind, LoadPoll::Failed);
    std::filesystem::remove(path);
    // A load replaced before it finished is joined, not leaked or raced.
    engine.beginLoad("builtin:sample");
    engine.beginLoad("builtin:sample");
    EXPECT_EQ(waitForLoad(engine).kind, LoadPoll::Ready);
}

TEST(KioskScanName, IsShortAndSafeForFileNames) {
    EXPECT_EQ(engine::scanShortName("builtin:sample"), "sample");
    EXPECT_EQ(engine::scanShortName("/data/CT sarcoma.nii.gz"), "CT_sarcoma");
    EXPECT_EQ(engine::scanShortName("/data/series/"), "series");
    EXPECT_EQ(engine::scanShortName("/"), "scan");
}

class KioskScreen : public GpuTest {};

// A 2x2 picture of four colours, row 0 on top.
unsigned int quadrantPicture(gpu::Texture& holder) {
    holder = gpu::createTexture();
    glBindTexture(GL_TEXTURE_2D, holder.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 2, 2);
    const std::uint8_t px[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return holder.id();
}

TEST_F(KioskScreen, PlacesPicturesTopDownAndTurnsTheScreenAsMounted) {
    gpu::Texture holder;
    const unsigned int picture = quadrantPicture(holder);
    const auto colourAt = [](const RgbaImage& img, int x, int y) {
        const std::uint8_t* p = img.at(x, y);
        return glm::ivec3(p[0], p[1], p[2]);
    };
    kiosk::ScreenCompositor screen({40, 30}, 0);
    screen.begin({0.0F, 0.0F, 0.0F});
    screen.drawPicture(picture, {2, 2}, ui::Rect{10, 5, 20, 20});
    const RgbaImage logical = screen.capture();
    EXPECT_EQ(colourAt(logical, 12, 7), glm::ivec3(255, 0, 0));  // top left: red
    EXPECT_EQ(colourAt(logical, 27, 7), glm::ivec3(0, 255, 0));  // top right: green
    EXPECT_EQ(colourAt(logical, 12, 22), glm::ivec3(0, 0, 255)); // bottom left: blue
    EXPECT_EQ(colourAt(logical, 5, 5), glm::ivec3(0, 0, 0));     // outside the rect
    EXPECT_EQ(logical.at(5, 5)[3], 255);

    // Mounted a quarter turn clockwise: the logical screen is 30x40, and its top-left corner
    // shows at the display's top right.
    kiosk::ScreenCompositor turned({40, 30}, 90);
    EXPECT_EQ(turned.size(), glm::ivec2(30, 40));
    turned.begin({0.0F, 0.0F, 0.0F});
    turned.drawPicture(picture, {2, 2}, ui::Rect{0, 0, 30, 40});
    gpu::Texture display = gpu::createTexture();
    glBindTexture(GL_TEXTURE_2D, display.id());
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 40, 30);
    GLuint fb = 0;
    glGenFramebuffers(1, &fb);
    gpu::Framebuffer displayFb(fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, display.id(), 0);
    turned.present(fb, {40, 30});
    std::vector<std::uint8_t> px(40 * 30 * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
    glReadPixels(0, 0, 40, 30, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    // GL rows bottom-up: display row y from the top is GL row 29 - y.
    const auto displayAt = [&](int x, int y) {
        const std::uint8_t* p = px.data() + 4 * ((29 - y) * 40 + x);
        return glm::ivec3(p[0], p[1], p[2]);
    };
    EXPECT_EQ(displayAt(37, 2), glm::ivec3(255, 0, 0));  // logical top left -> display top right
    EXPECT_EQ(displayAt(37, 27), glm::ivec3(0, 255, 0)); // logical top right -> bottom right
    EXPECT_EQ(displayAt(2, 2), glm::ivec3(0, 0, 255));   // logical bottom left -> top left
    EXPECT_THROW(kiosk::ScreenCompositor({40, 30}, 45), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
