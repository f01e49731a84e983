// The frame loop's pacing decisions, without a GPU: how many solver iterations fit a frame and
// how a slow view is previewed and refined in bands, and how the split follows the operator.
#include "kiosk/iteration_budget.hpp"
#include "kiosk/operator_pacing.hpp"
#include "kiosk/view_refiner.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace steerseg::test {
namespace {

using kiosk::IterationBudget;
using kiosk::ViewRefiner;

// Runs `frames` frames of a solver whose iterations cost `cost` seconds each, in frames that
// take `other` seconds besides the solver; returns the iterations per frame, how many frames
// ran none, and the solver's part of the time.
struct Simulated {
    double perFrame = 0.0;
    int skipped = 0;
    double solverShare = 0.0;
};
Simulated simulate(IterationBudget& budget, double cost, double other, int frames) {
    long long total = 0;
    int skipped = 0;
    double solver = 0.0;
    double all = 0.0;
    double last = 0.0;
    for (int f = 0; f < frames; ++f) {
        const int n = budget.next(last);
        skipped += n == 0 ? 1 : 0;
        total += n;
        budget.record(n, n * cost);
        last = other + n * cost;
        solver += n * cost;
        all += last;
    }
    return {static_cast<double>(total) / frames, skipped, solver / all};
}

TEST(IterationBudget, StartsAtTheMinimumThenGivesTheSolverItsShare) {
    IterationBudget budget(0.5, 0.020, 2, 500);
    EXPECT_EQ(budget.next(0.0), 2);
    budget.record(2, 0.002); // 1 ms per iteration, the rest of a frame 10 ms: about 10 a frame
    const Simulated fast = simulate(budget, 0.001, 0.010, 200);
    EXPECT_NEAR(fast.perFrame, 10.0, 1.5);
    EXPECT_EQ(fast.skipped, 0);
    EXPECT_NEAR(fast.solverShare, 0.5, 0.05);
    // The front shrank: 0.1 ms per iteration, about 100 a frame.
    EXPECT_NEAR(simulate(budget, 0.0001, 0.010, 200).perFrame, 100.0, 15.0);
}

// A GPU that draws a frame in 2 ms: the solver fills the 33 ms budget's share (up to the
// per-frame maximum) rather than half of a 2 ms frame, and the frames stay within the budget.
TEST(IterationBudget, FramesFarUnderTheBudgetLeaveTheSolverTheHeadroom) {
    IterationBudget budget(0.5, 0.033, 1, 64);
    budget.record(1, 0.0001);
    const Simulated gpu = simulate(budget, 0.0001, 0.002, 300);
    EXPECT_NEAR(gpu.perFrame, 64.0, 1.0);
    EXPECT_NEAR(gpu.solverShare, 0.0064 / 0.0084, 0.02); // the frame's maximum bounds it
    IterationBudget uncapped(0.5, 0.033, 1, 10000);
    uncapped.record(1, 0.0001);
    const Simulated most = simulate(uncapped, 0.0001, 0.002, 300);
    EXPECT_NEAR(most.perFrame, 165.0, 5.0); // the budget's share, 16.5 ms
    EXPECT_LE(0.002 + most.perFrame * 0.0001, 0.033);
}

TEST(IterationBudget, ASlowSolverRunsEveryFewFramesAndKeepsItsShare) {
    IterationBudget budget(0.5, 0.033, 1, 64);
    EXPECT_EQ(budget.next(0.0), 1);
    budget.record(1, 0.090); // one iteration costs several frames' share
    const Simulated slow = simulate(budget, 0.090, 0.030, 300);
    EXPECT_NEAR(slow.solverShare, 0.5, 0.05);
    EXPECT_GT(slow.skipped, 150); // most frames are quick ones, without the solver
}

TEST(IterationBudget, ClampsAndIgnoresNonsense) {
    IterationBudget budget(0.5, 0.020, 1, 50);
    EXPECT_EQ(budget.next(0.0), 1);
    budget.record(1, 1e-9);
    EXPECT_EQ(budget.next(0.020), 50);
    budget.record(0, 5.0);
    budget.record(3, std::numeric_limits<double>::quiet_NaN());
    budget.record(3, -1.0);
    EXPECT_EQ(budget.next(std::numeric_limits<double>::infinity()), 50);
    budget.record(1, 10.0); // one very slow call: a few frames go by, then it runs again
    int frames = 0;
    while (budget.next(0.020) == 0) {
        ASSERT_LT(++frames, 10000);
    }
    EXPECT_THROW(IterationBudget(0.0, 0.02, 1, 2), std::invalid_argument);
    EXPECT_THROW(IterationBudget(1.0, 0.02, 1, 2), std::invalid_argument);
    EXPECT_THROW(IterationBudget(0.5, 0.0, 1, 2), std::invalid_argument);
    EXPECT_THROW(IterationBudget(0.5, 0.02, 3, 2), std::invalid_argument);
}

TEST(IterationBudget, ASliceFillsItsTimeAndGrowsNoFasterThanItDoubles) {
    IterationBudget budget(0.5, 0.033, 1, 64);
    EXPECT_EQ(budget.forSlice(0.25), 1); // nothing measured yet
    budget.record(1, 0.002);
    // 2 ms an iteration: a quarter second holds 125, reached by doubling from the last count.
    std::vector<int> counts;
    for (int n = 0; n < 10; ++n) {
        counts.push_back(budget.forSlice(0.25));
        budget.record(counts.back(), counts.back() * 0.002);
    }
    EXPECT_EQ(counts.front(), 2);
    EXPECT_EQ(counts.back(), 125);
    for (std::size_t n = 1; n < counts.size(); ++n) {
        EXPECT_LE(counts[n], 2 * counts[n - 1]);
    }
    // Not bounded by the per-frame maximum (64): the operator is not waiting on the frame.
    EXPECT_GT(budget.forSlice(0.25), 64);
    EXPECT_EQ(budget.forSlice(0.0), 1);
    IterationBudget fixed(0.5, 0.033, 8, 8);
    fixed.record(8, 0.008);
    EXPECT_EQ(fixed.forSlice(0.25), 8);
}

// Nobody touching anything: the solver's slices make up most of the time, with a preview
// (and the panel) between them a few times a second; the first input turns the split back.
TEST(OperatorPacing, QuietGivesTheSolverMostOfTheMachineAndInputTurnsItBack) {
    kiosk::OperatorPacing pacing;
    IterationBudget budget(0.5, 0.033, 1, 64);
    budget.record(1, 0.004);
    pacing.input(0.0);
    double now = 0.0;
    double solver = 0.0;
    int frames = 0;
    double last = 0.033;
    const double drawing = 0.030; // a preview, the panel and the present
    while (now < 10.0) {
        const double slice = pacing.solverSlice(now);
        const int n = slice > 0.0 ? budget.forSlice(slice) : budget.next(last);
        budget.record(n, n * 0.004);
        last = drawing + n * 0.004;
        solver += n * 0.004;
        now += last;
        ++frames;
    }
    EXPECT_GT(solver / now, 0.8);
    EXPECT_GT(frames / now, 1.5); // a preview or two a second
    EXPECT_TRUE(pacing.quiet(now));
    pacing.input(now);
    EXPECT_FALSE(pacing.quiet(now + 0.1));
    EXPECT_EQ(pacing.solverSlice(now + 0.1), 0.0);
    EXPECT_TRUE(pacing.quiet(now + 0.6));
}

// The press that starts a run hands the machine to the solver: no budget frames after it, and
// the slices start small (the first picture at once) and double.
TEST(OperatorPacing, StartingARunHandsTheMachineToTheSolverFromItsFirstSlice) {
    kiosk::OperatorPacing pacing;
    pacing.input(5.0);
    EXPECT_FALSE(pacing.quiet(5.1));
    pacing.runStarted();
    EXPECT_TRUE(pacing.quiet(5.1));
    EXPECT_DOUBLE_EQ(pacing.solverSlice(5.1), 0.5);
    pacing.input(5.2); // the next touch turns the split back as any does
    EXPECT_EQ(pacing.solverSlice(5.3), 0.0);

    IterationBudget budget(0.5, 0.033, 1, 64);
    budget.record(100, 0.4);               // the last run's slices: 100 iterations of 4 ms
    const int fits = budget.forSlice(0.5); // 0.5 s at 4 ms, give or take the rounding
    EXPECT_NEAR(fits, 125, 1);
    budget.restartSlices();
    std::vector<int> counts;
    for (int k = 0; k < 9; ++k) {
        counts.push_back(budget.forSlice(0.5));
        budget.record(counts.back(), counts.back() * 0.004);
    }
    EXPECT_EQ(std::vector<int>(counts.begin(), counts.begin() + 7),
              (std::vector<int>{1, 2, 4, 8, 16, 32, 64}));
    EXPECT_NEAR(counts[7], fits, 1); // then what the slice fits, no more
    EXPECT_NEAR(counts[8], fits, 1);
}

TEST(OperatorPacing, TilesGrowOnceQuietOrAwaitedAndTheScreenIsComposedWhenItChanges) {
    kiosk::OperatorPacing pacing;
    pacing.input(1.0);
    EXPECT_DOUBLE_EQ(pacing.refineSeconds(1.1, 0.02, false), 0.02);
    EXPECT_DOUBLE_EQ(pacing.refineSeconds(1.1, 0.02, true), 0.1);
    EXPECT_DOUBLE_EQ(pacing.refineSeconds(2.0, 0.02, false), 0.1);
    EXPECT_DOUBLE_EQ(pacing.refineSeconds(2.0, 0.5, false), 0.5);
    EXPECT_TRUE(pacing.screenDue(2.0, false)); // never composed
    EXPECT_FALSE(pacing.screenDue(2.1, false));
    EXPECT_TRUE(pacing.screenDue(2.1, true));
    EXPECT_FALSE(pacing.screenDue(2.3, false));
    EXPECT_TRUE(pacing.screenDue(2.4, false)); // the interval is up
}

// A model of a software rasteriser: 20 microseconds per pixel.
constexpr double kSecondsPerPixel = 20e-6;

double cost(const ViewRefiner::Plan& p) {
    if (p.kind == ViewRefiner::Plan::Tile) {
        return kSecondsPerPixel * p.region.z * p.region.w;
    }
    return kSecondsPerPixel * p.size.x * p.size.y;
}

TEST(ViewRefiner, PreviewsFitTheFrameThenTilesCompleteTheFullPicture) {
    ViewRefiner refiner(0.5);
    const glm::ivec2 full(800, 600);
    const double frame = 0.020;
    ViewRefiner::Plan p = refiner.plan(full, frame);
    ASSERT_EQ(p.kind, ViewRefiner::Plan::Preview);
    refiner.drawn(p, cost(p));
    EXPECT_TRUE(refiner.anyReady());
    EXPECT_FALSE(refiner.fullReady());
    // Still moving: the next preview is sized to the learned cost and fits the frame.
    refiner.changed();
    p = refiner.plan(full, frame);
    ASSERT_EQ(p.kind, ViewRefiner::Plan::Preview);
    EXPECT_LE(cost(p), frame * 1.1);
    EXPECT_GT(cost(p), frame * 0.5);
    refiner.drawn(p, cost(p));
    // Still: tiles that each fit the frame and cover every pixel exactly once.
    std::vector<int> covered(static_cast<std::size_t>(full.x * full.y), 0);
    int frames = 0;
    while (!refiner.fullReady()) {
        p = refiner.plan(full, frame);
        ASSERT_EQ(p.kind, ViewRefiner::Plan::Tile);
        EXPECT_EQ(p.size, full);
        EXPECT_LE(cost(p), frame * 1.1);
        for (int y = p.region.y; y < p.region.y + p.region.w; ++y) {
            for (int x = p.region.x; x < p.region.x + p.region.z; ++x) {
                ++covered[static_cast<std::size_t>(y * full.x + x)];
            }
        }
        refiner.drawn(p, cost(p));
        ASSERT_LT(++frames, 100000);
    }
    EXPECT_TRUE(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }));
    EXPECT_EQ(refiner.plan(full, frame).kind, ViewRefiner::Plan::Nothing);
    // A faster frame budget on the same picture: whole bands of rows.
    refiner.changed();
    p = refiner.plan(full, 1.0);
    refiner.drawn(p, cost(p));
    p = refiner.plan(full, 1.0);
    EXPECT_EQ(p.region.z, full.x);
    EXPECT_EQ(p.region.w % 8, 0);
    // A change mid-way starts over with a preview.
    refiner.changed();
    EXPECT_FALSE(refiner.fullReady());
    EXPECT_EQ(refiner.plan(full, frame).kind, ViewRefiner::Plan::Preview);
}

// The first preview pays for compiling the shader (seconds for a few thousand pixels); the
// tiles after it, with a dispatch's fixed cost on top of the per-pixel one, must still grow to
// fill their time within a few frames, not stay at 8x8 pixels (the refinement at a twentieth
// of the renderer's speed the issue measured).
TEST(ViewRefiner, TilesGrowToTheirTimeAfterASlowFirstPreview) {
    ViewRefiner refiner(0.5);
    const glm::ivec2 full(800, 600);
    ViewRefiner::Plan p = refiner.plan(full, 0.02);
    ASSERT_EQ(p.kind, ViewRefiner::Plan::Preview);
    refiner.drawn(p, 5.0); // the compile
    const double fixed = 0.003;
    int frames = 0;
    double total = 0.0;
    while (!refiner.fullReady()) {
        p = refiner.plan(full, 0.1);
        ASSERT_EQ(p.kind, ViewRefiner::Plan::Tile);
        const double spent = fixed + cost(p);
        EXPECT_LE(spent, 0.2 + fixed); // at most twice its time
        total += spent;
        refiner.drawn(p, spent);
        ASSERT_LT(++frames, 400) << "the tiles never grew";
    }
    // 800x600 at 20 us a pixel is 9.6 s: in tiles of about 0.1 s, the fixed costs a few %.
    EXPECT_LT(frames, 170);
    EXPECT_LT(total, 1.1 * kSecondsPerPixel * full.x * full.y);
}

TEST(ViewRefiner, AFastMachineDrawsTheFullPictureAsItsPreview) {
    ViewRefiner refiner(1.0);
    const glm::ivec2 full(1920, 1080);
    ViewRefiner::Plan p = refiner.plan(full, 0.016);
    refiner.drawn(p, 1e-9 * p.size.x * p.size.y);
    refiner.changed();
    p = refiner.plan(full, 0.016);
    EXPECT_EQ(p.size, full);
    refiner.drawn(p, 0.001);
    EXPECT_TRUE(refiner.fullReady());
    EXPECT_EQ(refiner.plan(full, 0.016).kind, ViewRefiner::Plan::Nothing);
}

TEST(ViewRefiner, ASizeChangeRestartsAndEmptySizesDrawNothing) {
    ViewRefiner refiner(1.0);
    ViewRefiner::Plan p = refiner.plan({100, 100}, 1.0); // unknown cost: a small preview first
    EXPECT_LT(p.size.x, 100);
    refiner.drawn(p, 0.0001);
    refiner.changed();
    p = refiner.plan({100, 100}, 1.0);
    refiner.drawn(p, 0.0001);
    EXPECT_TRUE(refiner.fullReady());
    EXPECT_EQ(refiner.plan({120, 100}, 1.0).kind, ViewRefiner::Plan::Preview);
    EXPECT_EQ(refiner.plan({0, 100}, 1.0).kind, ViewRefiner::Plan::Nothing);
    // Tiles never go below one 8x8 work group, even with no time at all.
    ViewRefiner slow(0.25);
    p = slow.plan({64, 64}, 0.0);
    slow.drawn(p, 1.0);
    p = slow.plan({64, 64}, 0.0);
    ASSERT_EQ(p.kind, ViewRefiner::Plan::Tile);
    EXPECT_EQ(p.region, glm::ivec4(0, 0, 8, 8));
}

} // namespace
} // namespace steerseg::test
