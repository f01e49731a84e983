// The settle rule on front series (no GPU): a jittering front has settled, a creeping one and
// one that pauses between two growths have not.
#include "front_series.hpp"
#include "solver/settle_watch.hpp"

#include <cstdint>
#include <gtest/gtest.h>
#include <optional>
#include <vector>

namespace steerseg::test {
namespace {

using solver::FrontCheck;
using solver::SettleWatch;

constexpr int kCheck = 16; // iterations per check, the solver's default
constexpr int kWindow = 256;
constexpr double kTolerance = 0.05;

// One check per kCheck iterations with the given net voxels, each on a front of `front`
// voxels, churning: `churn` more voxels come in and go out than the net. Returns the index of
// the check at which the watch said settled.
std::optional<int> feed(SettleWatch& watch, const std::vector<std::int64_t>& nets,
                        std::uint32_t front, std::uint32_t churn = 400, int firstIteration = 0) {
    for (std::size_t n = 0; n < nets.size(); ++n) {
        const std::int64_t net = nets[n];
        FrontCheck c;
        c.iteration = firstIteration + kCheck * static_cast<int>(n + 1);
        c.time = 0.01F * static_cast<float>(c.iteration);
        c.gained = churn + static_cast<std::uint32_t>(net > 0 ? net : 0);
        c.lost = churn + static_cast<std::uint32_t>(net < 0 ? -net : 0);
        c.front = front;
        if (watch.observe(c)) {
            return static_cast<int>(n);
        }
    }
    return std::nullopt;
}

// A front held by noise: the voxels it holds beyond its rest position go up and down within
// 60, so each check's net is the difference of two such excesses.
std::vector<std::int64_t> jitter(int checks) {
    std::vector<std::int64_t> nets;
    std::int64_t last = 0;
    for (int n = 0; n < checks; ++n) {
        const std::int64_t excess = (static_cast<std::int64_t>(n) * 7919) % 61;
        nets.push_back(excess - last);
        last = excess;
    }
    return nets;
}

TEST(SettleWatch, AJitteringFrontSettlesAfterOneWindow) {
    SettleWatch watch(kWindow, kTolerance);
    // The first check sets the clock; a full window of checks after it.
    EXPECT_EQ(feed(watch, jitter(100), 4000), kWindow / kCheck);
    // The old rule's "no voxel changed side" never holds here: 400 voxels flip each way.
}

TEST(SettleWatch, ASteadyCreepDoesNotSettle) {
    SettleWatch watch(kWindow, kTolerance);
    // 20 voxels a check on a front of 4000: 0.08 voxel a window, 1.5 voxels in 5000 iterations.
    EXPECT_FALSE(feed(watch, std::vector<std::int64_t>(5000 / kCheck, 20), 4000));
    // The same creep hidden in jitter.
    std::vector<std::int64_t> nets = jitter(5000 / kCheck);
    for (std::int64_t& net : nets) {
        net += 20;
    }
    watch.reset();
    EXPECT_FALSE(feed(watch, nets, 4000));
    // Shrinking as steadily is no rest either.
    watch.reset();
    EXPECT_FALSE(feed(watch, std::vector<std::int64_t>(5000 / kCheck, -20), 4000));
    // Half that pace (0.04 voxel a window) is below the tolerance: settled.
    watch.reset();
    EXPECT_TRUE(feed(watch, std::vector<std::int64_t>(5000 / kCheck, 10), 4000));
}

TEST(SettleWatch, APauseBetweenTwoGrowthsIsNoStop) {
    SettleWatch watch(kWindow, kTolerance);
    std::vector<std::int64_t> nets(20, 800); // growing
    const std::vector<std::int64_t> pause = jitter(14);
    nets.insert(nets.end(), pause.begin(), pause.end()); // 224 iterations at rest
    nets.insert(nets.end(), 20, 800);                    // growing again
    EXPECT_FALSE(feed(watch, nets, 3000));
    // A rest longer than the window after the same growth is a stop, one window into it.
    watch.reset();
    std::vector<std::int64_t> rest(20, 800);
    const std::vector<std::int64_t> still = jitter(40);
    rest.insert(rest.end(), still.begin(), still.end());
    EXPECT_EQ(feed(watch, rest, 3000), 20 + kWindow / kCheck - 1);
}

TEST(SettleWatch, TheToleranceIsRelativeToTheFront) {
    // The same 100 voxels a window: a mean displacement of 0.2 voxel on a front of 500, 0.01
    // on one of 10,000.
    std::vector<std::int64_t> nets(40, 0);
    for (std::size_t n = 0; n < nets.size(); n += 16) {
        nets[n] = 100;
    }
    SettleWatch small(kWindow, kTolerance);
    EXPECT_FALSE(feed(small, nets, 500));
    SettleWatch large(kWindow, kTolerance);
    EXPECT_TRUE(feed(large, nets, 10000));
}

TEST(SettleWatch, AResetStartsANewWindow) {
    SettleWatch watch(kWindow, kTolerance);
    ASSERT_TRUE(feed(watch, jitter(40), 4000));
    watch.reset();
    // An edit: the window starts again at the next check, whatever came before.
    EXPECT_EQ(feed(watch, jitter(40), 4000, 400, 1000), kWindow / kCheck);
}

TEST(SettleWatch, ChecksWithoutIterationsAreIgnored) {
    SettleWatch watch(kWindow, kTolerance);
    FrontCheck c;
    c.front = 1000;
    EXPECT_FALSE(watch.observe(c));
    for (int n = 0; n < 40; ++n) {
        EXPECT_FALSE(watch.observe(c)) << "no iteration, no window";
    }
}

// The iteration at which a recorded run would have settled, if it did.
std::optional<int> settledAt(const std::string& name) {
    SettleWatch watch(kWindow, kTolerance);
    for (const FrontCheck& c : frontSeries(name)) {
        if (watch.observe(c)) {
            return c.iteration;
        }
    }
    return std::nullopt;
}

TEST(SettleWatch, ARealFrontThatSlowsSettlesOnlyAtItsEnd) {
    // The lung tumour's threshold front gains 200-350 voxels a check for 2000 iterations, then
    // slows to 34 at the 3000 cap: settled once it gains under ~1000 in a window (0.05 of its
    // front of 21,000), not while it still grows.
    const auto at = settledAt("lung_threshold_slowing.txt");
    ASSERT_TRUE(at.has_value());
    EXPECT_GE(*at, 2600);
    EXPECT_LE(*at, 3000);
}

TEST(SettleWatch, TheLiversSlowFillSettlesWhenItBarelyMoves) {
    // 200 voxels a check on a front of 5,000-10,000 for 2000 iterations, then ever fewer:
    // settled when the window's gain falls below 0.05 of the front (~50 voxels a check on its
    // 15,000), in the last quarter of the 6500-iteration run.
    const auto at = settledAt("liver_threshold_fill.txt");
    ASSERT_TRUE(at.has_value());
    EXPECT_GE(*at, 4500);
}

} // namespace
} // namespace steerseg::test
