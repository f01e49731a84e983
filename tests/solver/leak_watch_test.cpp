// The leak watch's rule on growth series (no GPU): what must and must not read as a leak.
#include "solver/leak_watch.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

using solver::GrowthSample;
using solver::LeakWatch;

// One check per unit of time; `nets` are the voxels gained per check; every gain lies in a box
// that moves along i with the check's index.
std::optional<model::LeakSite> feed(LeakWatch& watch, const std::vector<long>& nets,
                                    int* at = nullptr) {
    watch.observe({0.0F, 0, 0, false, {}, {}});
    for (std::size_t n = 0; n < nets.size(); ++n) {
        const int i = static_cast<int>(n);
        GrowthSample s{static_cast<float>(n + 1),
                       static_cast<int>(16 * (n + 1)),
                       nets[n],
                       nets[n] > 0,
                       {i, 0, 0},
                       {i, 2, 2}};
        if (auto site = watch.observe(s)) {
            if (at != nullptr) {
                *at = i;
            }
            return site;
        }
    }
    return std::nullopt;
}

TEST(LeakWatch, SteadyOrSlowingGrowthIsNoLeak) {
    LeakWatch watch;
    EXPECT_FALSE(feed(watch, {100, 400, 900, 1600, 2500, 3600, 4900}));
    watch.reset();
    // A front filling a ball: growing, then slowing to a stop, with noise on the way down.
    EXPECT_FALSE(feed(watch, {200, 800, 1500, 1400, 900, 300, 60, 20, 35, 10, 25, 0, 5, 0}));
}

TEST(LeakWatch, GrowthThatJumpsAfterASlowdownIsALeakAtTheJump) {
    LeakWatch watch;
    int at = -1;
    const auto site =
        feed(watch, {200, 800, 1500, 1400, 600, 100, 20, 15, 20, 150, 400, 900, 1500}, &at);
    ASSERT_TRUE(site.has_value());
    EXPECT_EQ(at, 10); // the second check of the jump
    EXPECT_EQ(site->lo.x, 9);
    EXPECT_EQ(site->hi.x, 10);
    EXPECT_EQ(site->iteration, 16 * 11);
    EXPECT_EQ(site->sign, model::LeakSign::GrowthJump);
}

TEST(LeakWatch, OneNoisyCheckIsNoLeak) {
    LeakWatch watch;
    EXPECT_FALSE(feed(watch, {200, 800, 1500, 1400, 600, 100, 20, 15, 120, 10, 5, 0, 0}));
}

TEST(LeakWatch, ALeakIsSaidOnceUntilTheOperatorActs) {
    LeakWatch watch;
    const std::vector<long> leak = {200, 800, 1500, 600, 100, 20, 150, 400, 900};
    ASSERT_TRUE(feed(watch, leak));
    GrowthSample more{100.0F, 2000, 5000, true, {0, 0, 0}, {1, 1, 1}};
    EXPECT_FALSE(watch.observe(more));
    watch.reset();
    EXPECT_TRUE(feed(watch, leak));
}

// A recorded run's checks (tests/data/growth): iteration, evolved time, net voxels.
std::vector<GrowthSample> recorded(const std::string& name) {
    std::ifstream in(std::filesystem::path(STEERSEG_GROWTH_DATA_DIR) / name);
    std::vector<GrowthSample> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::istringstream fields(line);
        GrowthSample s;
        long net = 0;
        fields >> s.iteration >> s.time >> net;
        s.net = net;
        s.anyGained = net > 0;
        s.gainHi = {1, 1, 1};
        out.push_back(s);
    }
    return out;
}

TEST(LeakWatch, AFrontCreepingAFewVoxelsACheckIsNoLeak) {
    const std::vector<GrowthSample> run = recorded("liver_threshold_creep.txt");
    ASSERT_EQ(run.size(), 403U);
    LeakWatch watch;
    for (const GrowthSample& s : run) {
        // Read as a leak at its last check (iteration 6460) while one quiet check of 8 voxels
        // stood as the floor; the floor over four calm checks holds at the creep's own pace.
        EXPECT_FALSE(watch.observe(s)) << "at iteration " << s.iteration;
    }
}

TEST(LeakWatch, ABreakThroughAfterTheCreepIsALeak) {
    std::vector<GrowthSample> run = recorded("liver_threshold_creep.txt");
    ASSERT_FALSE(run.empty());
    LeakWatch watch;
    for (const GrowthSample& s : run) {
        watch.observe(s);
    }
    // The creep's checks span about 0.04 units of time; the front then breaks through.
    GrowthSample next = run.back();
    int jumpChecks = 0;
    for (const long net : {25L, 90L, 160L}) {
        next.iteration += 16;
        next.time += 0.04F;
        next.net = net;
        ++jumpChecks;
        if (const auto site = watch.observe(next)) {
            EXPECT_EQ(jumpChecks, 3); // 25 is the creep's pace; 90 and 160 are the jump
            EXPECT_EQ(site->iteration, next.iteration);
            return;
        }
    }
    FAIL() << "a growth of 4x and 6x the creep's pace was not read as a leak";
}

TEST(LeakWatch, NoTimeElapsedGivesNoRate) {
    LeakWatch watch;
    watch.observe({1.0F, 0, 0, false, {}, {}});
    EXPECT_FALSE(watch.observe({1.0F, 16, 1000, true, {}, {}}));
    EXPECT_EQ(watch.lastRate(), 0.0);
}

} // namespace
} // namespace steerseg::test
