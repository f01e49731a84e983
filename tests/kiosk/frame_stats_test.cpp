// The kiosk's frame statistics, as the benchmark (tools/bench-kiosk.sh) reads them.
#include "kiosk/frame_stats.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

using kiosk::FrameStats;

TEST(FrameStats, PercentilesAreNearestRankAndTheTotalIsTheSum) {
    std::vector<double> samples;
    for (int i = 100; i >= 1; --i) {
        samples.push_back(i * 1e-3);
    }
    const kiosk::Percentiles p = kiosk::percentiles(samples);
    EXPECT_EQ(p.count, 100U);
    EXPECT_DOUBLE_EQ(p.p50, 0.050);
    EXPECT_DOUBLE_EQ(p.p90, 0.090);
    EXPECT_DOUBLE_EQ(p.p99, 0.099);
    EXPECT_DOUBLE_EQ(p.max, 0.100);
    EXPECT_NEAR(p.total, 5.050, 1e-9);
    const kiosk::Percentiles none = kiosk::percentiles({});
    EXPECT_EQ(none.count, 0U);
    EXPECT_EQ(none.total, 0.0);
}

TEST(FrameStats, WritesRatesOverTheTimeEvolvingAndDrawing) {
    FrameStats stats;
    stats.frame(0.25, true);
    stats.frame(0.75, true);
    stats.frame(0.01, false);
    stats.iterations(30, 0.4);
    stats.iterations(10, 0.1);
    stats.drawn(2e6, 0.5);
    stats.latency(0.3);
    stats.frameWait(1.5);
    stats.viewSizes({{640, 400}, {320, 200}, {320, 200}});
    const auto path = std::filesystem::temp_directory_path() / "steerseg_frame_stats_test.json";
    stats.write(path, "offscreen 8x8");
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
    std::filesystem::remove(path);
    EXPECT_EQ(j["display"], "offscreen 8x8");
    EXPECT_EQ(j["frames_evolving"]["count"], 2);
    EXPECT_NEAR(j["frames_evolving"]["total_s"].get<double>(), 1.0, 1e-12);
    EXPECT_EQ(j["frames_idle"]["count"], 1);
    EXPECT_EQ(j["iterations"], 40);
    EXPECT_NEAR(j["iterations_per_second"].get<double>(), 40.0, 1e-9); // 40 over 1 s evolving
    EXPECT_NEAR(j["solver_seconds"].get<double>(), 0.5, 1e-12);
    EXPECT_NEAR(j["draw_seconds"].get<double>(), 0.5, 1e-12);
    EXPECT_NEAR(j["pixels_per_second"].get<double>(), 4e6, 1e-3);
    EXPECT_NEAR(j["latency"]["p50_ms"].get<double>(), 300.0, 1e-9);
    EXPECT_EQ(j["frame_waits_s"], nlohmann::json::array({1.5}));
    EXPECT_EQ(j["view_sizes"][0], nlohmann::json::array({640, 400}));
    EXPECT_EQ(j["view_sizes"].size(), 3U);
}

TEST(FrameStats, NothingEvolvingGivesNoRateAndABadPathThrows) {
    FrameStats stats;
    stats.frame(0.02, false);
    const auto path = std::filesystem::temp_directory_path() / "steerseg_frame_stats_idle.json";
    stats.write(path, "idle");
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
    std::filesystem::remove(path);
    EXPECT_EQ(j["iterations_per_second"], 0.0);
    EXPECT_THROW(stats.write("/nonexistent-dir/stats.json", "x"), std::runtime_error);
}

} // namespace
} // namespace steerseg::test
