// The runaway rule on front series (no GPU): a fill that stops, or creeps, or fills a second,
// smaller part is no runaway; one that spills on into tissue of the same intensity is.
#include "front_series.hpp"
#include "solver/runaway_watch.hpp"

#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <numbers>
#include <optional>
#include <vector>

namespace steerseg::test {
namespace {

using solver::FrontCheck;
using solver::RunawayWatch;

constexpr int kCheck = 16;
constexpr double kFactor = 2.0; // model::SolverOptions::runawayFactor
constexpr double kPi = std::numbers::pi;

double ballVolume(double r) {
    return 4.0 / 3.0 * kPi * r * r * r;
}
// A ball's front voxels: both sides of its surface.
std::uint32_t ballFront(double r) {
    return static_cast<std::uint32_t>(std::lround(8.0 * kPi * r * r));
}

// A series of checks from the radii of up to two balls (the structure and what grows beside
// it), one check per kCheck iterations; gains lie in a box that moves along i with the check.
struct Series {
    std::vector<FrontCheck> checks;
    double lastVolume = 0.0;
    void add(double r1, double r2) {
        const double volume = ballVolume(r1) + ballVolume(r2);
        FrontCheck c;
        c.iteration = kCheck * static_cast<int>(checks.size() + 1);
        const auto net = static_cast<std::int64_t>(std::lround(volume - lastVolume));
        lastVolume = volume;
        c.gained = static_cast<std::uint32_t>(std::max<std::int64_t>(net, 0)) + 50;
        c.lost = static_cast<std::uint32_t>(std::max<std::int64_t>(-net, 0)) + 50;
        c.front = ballFront(r1) + ballFront(r2);
        const int i = static_cast<int>(checks.size());
        c.gainLo = {i, 0, 0};
        c.gainHi = {i, 3, 3};
        checks.push_back(c);
    }
};

// The index of the check at which the watch said runaway.
std::optional<int> feed(RunawayWatch& watch, const std::vector<FrontCheck>& checks) {
    for (std::size_t n = 0; n < checks.size(); ++n) {
        if (watch.observe(checks[n])) {
            return static_cast<int>(n);
        }
    }
    return std::nullopt;
}

// A seed of radius 3 grows at `pace` voxels a check to radius `r`, then rests `rest` checks.
Series fill(double r, double pace = 4.0, int rest = 40) {
    Series s;
    for (double radius = 3.0; radius < r; radius += pace) {
        s.add(radius, 0.0);
    }
    for (int n = 0; n < rest; ++n) {
        s.add(r, 0.0);
    }
    return s;
}

TEST(RunawayWatch, AFillThatStopsIsNoRunaway) {
    for (const double r : {8.0, 20.0, 60.0}) {
        RunawayWatch watch(kFactor);
        EXPECT_FALSE(feed(watch, fill(r).checks)) << "ball of radius " << r;
    }
}

TEST(RunawayWatch, AFillThatSpillsOnIsARunawayOnceItTripled) {
    // The structure (r = 12) is full at check 3; from there, a region of the same intensity
    // beside it fills from a neck at the same pace, and goes on to 5 times the structure.
    Series s = fill(12.0, 3.0, 0);
    const int full = static_cast<int>(s.checks.size());
    for (double rho = 1.0; rho < 12.0 * std::cbrt(5.0); rho += 1.0) {
        s.add(12.0, rho);
    }
    RunawayWatch watch(kFactor);
    const auto at = feed(watch, s.checks);
    ASSERT_TRUE(at.has_value());
    // The bound is the volume a ball with the front at the slowdown holds, just above the
    // structure's (the spill's first voxels are in that front): said as the spill passes
    // twice it, at rho = 16 (2.4 times the structure).
    const int passed = full + 15;
    EXPECT_GE(*at, passed - 1);
    EXPECT_LE(*at, passed + 1);
}

TEST(RunawayWatch, TheSiteIsWhereTheFrontGrewSinceTheSlowdown) {
    Series s = fill(12.0, 3.0, 0);
    for (double rho = 1.0; rho < 30.0; rho += 1.0) {
        s.add(12.0, rho);
    }
    RunawayWatch watch(kFactor);
    std::optional<model::LeakSite> site;
    for (const FrontCheck& c : s.checks) {
        if ((site = watch.observe(c))) {
            EXPECT_EQ(site->iteration, c.iteration);
            EXPECT_EQ(site->hi.x, c.gainHi.x);
            break;
        }
    }
    ASSERT_TRUE(site.has_value());
    EXPECT_GT(site->lo.x, 2); // not the structure's own fill
    EXPECT_EQ(site->sign, model::LeakSign::RunawayFill);
    // Said once until the operator acts.
    FrontCheck more = s.checks.back();
    more.iteration += 10 * kCheck;
    more.gained = 100000;
    EXPECT_FALSE(watch.observe(more));
    watch.reset();
    EXPECT_TRUE(feed(watch, s.checks));
}

TEST(RunawayWatch, ASmallerSecondPartIsNoRunaway) {
    // Two lobes of one organ joined by a neck: the first (r = 20) fills, the front slows, then
    // the second (r = 15, 42% of the first) fills through the neck and everything stops.
    Series s = fill(20.0, 3.0, 0);
    for (double rho = 1.0; rho <= 15.0; rho += 1.0) {
        s.add(20.0, rho);
    }
    for (int n = 0; n < 40; ++n) {
        s.add(20.0, 15.0);
    }
    RunawayWatch watch(kFactor);
    EXPECT_FALSE(feed(watch, s.checks));
}

TEST(RunawayWatch, ASlowCreepAlongTheEdgeIsNoRunaway) {
    // A filled ball of radius 25 whose front creeps on at 20 voxels a check for 600 checks
    // (12,000 voxels against its 65,450: the liver's threshold front into its vessels).
    Series s = fill(25.0, 3.0, 2);
    RunawayWatch watch(kFactor);
    std::vector<FrontCheck> checks = s.checks;
    for (int n = 0; n < 600; ++n) {
        FrontCheck c = checks.back();
        c.iteration += kCheck;
        c.gained = 70;
        c.lost = 50;
        checks.push_back(c);
    }
    EXPECT_FALSE(feed(watch, checks));
}

TEST(RunawayWatch, AFillThatGrowsOnEverMoreSlowlyIsNoRunaway) {
    // A ball of radius 10 whose front spreads (30 more front voxels a check) and gains 300
    // voxels a check, one fewer each check: 45,000 voxels, 10x the ball, but ever more slowly.
    Series s = fill(10.0, 3.0, 0);
    std::vector<FrontCheck> checks = s.checks;
    for (std::uint32_t n = 0; n < 300; ++n) {
        FrontCheck c = checks.back();
        c.iteration += kCheck;
        c.gained = 50 + (300 - n);
        c.lost = 50;
        c.front += 30;
        checks.push_back(c);
    }
    RunawayWatch watch(kFactor);
    EXPECT_FALSE(feed(watch, checks));
    // At a steady 250 a check instead, the same spread is a runaway.
    for (std::size_t n = s.checks.size(); n < checks.size(); ++n) {
        checks[n].gained = 300;
    }
    RunawayWatch steady(kFactor);
    EXPECT_TRUE(feed(steady, checks));
}

TEST(RunawayWatch, TheLiversFillIsNoRunaway) {
    // It slows to a fifth of its first pace at iteration 540 and then gains 4x the ball its
    // front had (its top and bottom are cut by the scan's border, where no front is counted),
    // at a rate that stays near its reference (13.5 voxels an iteration) up to 1x and has fallen
    // by 16 % at 2x.
    RunawayWatch watch(kFactor);
    EXPECT_FALSE(feed(watch, frontSeries("liver_threshold_fill.txt")));
    EXPECT_GT(watch.lastRatio(), 3.0);
}

TEST(RunawayWatch, NoIterationsSayNothing) {
    RunawayWatch watch(kFactor);
    FrontCheck c;
    c.front = 100;
    c.gained = 1000;
    for (int n = 0; n < 10; ++n) {
        EXPECT_FALSE(watch.observe(c));
    }
}

TEST(RunawayWatch, ARealFrontThatSlowsIsNoRunaway) {
    // The lung tumour's threshold front: it slows to a fifth of its first checks' pace at
    // iteration 1196 and gains 0.39 of its bound by the cap.
    RunawayWatch watch(kFactor);
    EXPECT_FALSE(feed(watch, frontSeries("lung_threshold_slowing.txt")));
}

} // namespace
} // namespace steerseg::test
