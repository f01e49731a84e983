// The segmentation options' rules that need no GPU: what --speed classify takes as its inside
// examples once the scan is read.
#include "cli/segmentation_options.hpp"
#include "core/sample_phantom.hpp"

#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

cli::SegmentationRequest parse(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) {
        words.push_back(w);
    }
    const cli::Args args(words, cli::segmentationValueOptions(), cli::segmentationFlagOptions());
    return cli::parseSegmentation(args);
}

bool same(const model::Sphere& a, const model::Sphere& b) {
    return a.centre == b.centre && a.radius == b.radius;
}

TEST(SegmentationOptions, ClassifyTakesTheSeedsAsInsideExamples) {
    const Volume scan = makeSamplePhantom();
    cli::SegmentationRequest r = parse("--seed 80,56,52,5 --seed 70,50,50,3 --T 800 --eps 100 "
                                       "--alpha 0.5 --converge --speed classify "
                                       "--outside 20,20,20,4");
    cli::completeWithScan(r, scan);
    ASSERT_EQ(r.speed.inside.size(), 2U);
    EXPECT_TRUE(same(r.speed.inside[0], r.seeds[0]));
    EXPECT_TRUE(same(r.speed.inside[1], r.seeds[1]));

    // With --probe and --inside: those first, then the seeds.
    r = parse("--seed 80,56,52,5 --probe 80,56,52,4 --inside 82,56,52,2 --alpha 0.5 --converge "
              "--speed classify --outside 20,20,20,4");
    cli::completeWithScan(r, scan);
    ASSERT_EQ(r.speed.inside.size(), 3U);
    EXPECT_EQ(r.speed.inside[0].centre.x, 82.0F);
    EXPECT_TRUE(same(r.speed.inside[1], *r.probe));
    EXPECT_TRUE(same(r.speed.inside[2], r.seeds[0]));
}

TEST(SegmentationOptions, OtherSpeedsTakeNoExamples) {
    cli::SegmentationRequest r =
        parse("--seed 80,56,52,5 --probe 80,56,52,4 --alpha 0.5 --converge");
    cli::completeWithScan(r, makeSamplePhantom());
    EXPECT_TRUE(r.speed.inside.empty());
}

TEST(SegmentationOptions, ClassifyWithoutAnOutsideExampleIsAUsageError) {
    try {
        parse("--seed 80,56,52,5 --T 800 --eps 100 --converge --speed classify");
        FAIL() << "accepted";
    } catch (const cli::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("needs an outside example"), std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace steerseg::test
