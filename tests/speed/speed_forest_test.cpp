// The classifier speed's random forest on small 2-feature sets whose answer is known.
#include "speed/random_forest.hpp"
#include "speed/split_mix.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {
using speed::ForestParams;
using speed::RandomForest;
using speed::SplitMix;
namespace {

struct Set {
    std::vector<float> features; // 2 per sample
    std::vector<std::uint8_t> labels;
    void add(float x, float y, bool inside) {
        features.push_back(x);
        features.push_back(y);
        labels.push_back(inside ? 1 : 0);
    }
};

float uniform(SplitMix& rng) {
    return static_cast<float>(static_cast<double>(rng.next() >> 11U) * 0x1.0p-53);
}

// n points uniform over the unit square, inside where the rule says.
template <typename Rule> Set uniformSet(std::uint64_t seed, int n, Rule inside) {
    SplitMix rng(seed);
    Set set;
    for (int k = 0; k < n; ++k) {
        const float x = uniform(rng);
        const float y = uniform(rng);
        set.add(x, y, inside(x, y));
    }
    return set;
}

void expectSameForest(const RandomForest& a, const RandomForest& b) {
    ASSERT_EQ(a.nodes().size(), b.nodes().size());
    for (std::size_t n = 0; n < a.nodes().size(); ++n) {
        EXPECT_EQ(a.nodes()[n].feature, b.nodes()[n].feature);
        EXPECT_EQ(a.nodes()[n].threshold, b.nodes()[n].threshold);
        EXPECT_EQ(a.nodes()[n].left, b.nodes()[n].left);
        EXPECT_EQ(a.nodes()[n].value, b.nodes()[n].value);
    }
    EXPECT_EQ(a.roots(), b.roots());
    EXPECT_EQ(a.outOfBagAccuracy(), b.outOfBagAccuracy());
}

float predictAt(const RandomForest& f, float x, float y) {
    const std::vector<float> s{x, y};
    return f.predict(s);
}

TEST(SpeedForest, SeparatesTwoClusters) {
    SplitMix rng(7);
    Set set;
    for (int n = 0; n < 400; ++n) {
        set.add(2.0F + uniform(rng), 1.0F + uniform(rng), true);
        set.add(5.0F + uniform(rng), 3.0F + uniform(rng), false);
    }
    const RandomForest forest = RandomForest::train(set.features, set.labels, 2);
    EXPECT_GT(predictAt(forest, 2.5F, 1.5F), 0.9F);
    EXPECT_LT(predictAt(forest, 5.5F, 3.5F), -0.9F);
    EXPECT_GT(forest.outOfBagAccuracy(), 0.99);
    for (const float v : {predictAt(forest, -100.0F, 0.0F), predictAt(forest, 100.0F, 100.0F)}) {
        EXPECT_GE(v, -1.0F);
        EXPECT_LE(v, 1.0F);
    }
}

TEST(SpeedForest, LearnsXor) {
    // Inside where x and y are on the same side of 0.5: no single threshold separates it.
    const Set set = uniformSet(11, 2000, [](float x, float y) { return (x < 0.5F) == (y < 0.5F); });
    ForestParams params;
    params.featuresPerSplit = 2;
    const RandomForest forest = RandomForest::train(set.features, set.labels, 2, params);
    EXPECT_GT(predictAt(forest, 0.25F, 0.25F), 0.5F);
    EXPECT_GT(predictAt(forest, 0.75F, 0.75F), 0.5F);
    EXPECT_LT(predictAt(forest, 0.25F, 0.75F), -0.5F);
    EXPECT_LT(predictAt(forest, 0.75F, 0.25F), -0.5F);
    EXPECT_GT(forest.outOfBagAccuracy(), 0.95);
}

TEST(SpeedForest, TakesAnOutsideOfTwoTissues) {
    // Inside at middle intensities, outside both darker and brighter (fat and bone around
    // muscle): one threshold cannot say it, two splits can.
    SplitMix rng(13);
    Set set;
    for (int n = 0; n < 600; ++n) {
        set.add(40.0F + 10.0F * uniform(rng), uniform(rng), true);
        set.add((n % 2 == 0 ? 0.0F : 80.0F) + 10.0F * uniform(rng), uniform(rng), false);
    }
    const RandomForest forest = RandomForest::train(set.features, set.labels, 2);
    EXPECT_GT(predictAt(forest, 45.0F, 0.5F), 0.9F);
    EXPECT_LT(predictAt(forest, 5.0F, 0.5F), -0.9F);
    EXPECT_LT(predictAt(forest, 85.0F, 0.5F), -0.9F);
}

TEST(SpeedForest, BalancesClassesWhateverTheirCounts) {
    // Both classes drawn from one distribution, nine times as many inside: with equal priors
    // the forest leans to neither; counting samples would give about +0.8.
    SplitMix rng(3);
    Set set;
    for (int n = 0; n < 2000; ++n) {
        set.add(uniform(rng), uniform(rng), n % 10 != 0);
    }
    ForestParams params;
    params.minSamplesLeaf = 50;
    const RandomForest forest = RandomForest::train(set.features, set.labels, 2, params);
    double mean = 0.0;
    for (int n = 0; n < 100; ++n) {
        mean += static_cast<double>(predictAt(forest, uniform(rng), uniform(rng)));
    }
    EXPECT_NEAR(mean / 100.0, 0.0, 0.25);
}

TEST(SpeedForest, SameSeedSameForest) {
    SplitMix rng(5);
    Set set;
    for (int n = 0; n < 300; ++n) {
        const float x = uniform(rng);
        set.add(x, uniform(rng), x > 0.4F);
    }
    ForestParams params;
    params.trees = 8;
    const RandomForest a = RandomForest::train(set.features, set.labels, 2, params);
    const RandomForest b = RandomForest::train(set.features, set.labels, 2, params);
    expectSameForest(a, b);
    params.seed = 2;
    const RandomForest c = RandomForest::train(set.features, set.labels, 2, params);
    bool differs = c.nodes().size() != a.nodes().size();
    for (std::size_t n = 0; !differs && n < a.nodes().size(); ++n) {
        differs = a.nodes()[n].threshold != c.nodes()[n].threshold;
    }
    EXPECT_TRUE(differs);
}

TEST(SpeedForest, TheSameForestOnAnyNumberOfWorkers) {
    const Set set = uniformSet(6, 2000, [](float x, float y) { return x * x + y > 0.7F; });
    ForestParams params;
    params.trees = 13; // not a multiple of the workers: some build more trees than others
    params.workers = 1;
    const RandomForest one = RandomForest::train(set.features, set.labels, 2, params);
    for (const unsigned workers : {2U, 5U, 0U}) {
        params.workers = workers;
        SCOPED_TRACE(std::to_string(workers) + " workers");
        expectSameForest(one, RandomForest::train(set.features, set.labels, 2, params));
    }
}

TEST(SpeedForest, DepthIsBounded) {
    SplitMix rng(9);
    Set set;
    for (int n = 0; n < 1000; ++n) {
        set.add(uniform(rng), uniform(rng), (rng.next() & 1U) != 0); // noise: grows deep
    }
    ForestParams params;
    params.trees = 4;
    params.maxDepth = 3;
    const RandomForest forest = RandomForest::train(set.features, set.labels, 2, params);
    // A full binary tree of depth 3 has 15 nodes.
    EXPECT_LE(forest.nodes().size(), 4U * 15U);
}

std::string trainMessage(const Set& set, int featureCount, const ForestParams& params = {}) {
    try {
        (void)RandomForest::train(set.features, set.labels, featureCount, params);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "accepted";
}

TEST(SpeedForest, RefusesBadInput) {
    Set oneClass;
    oneClass.add(0.0F, 0.0F, true);
    oneClass.add(1.0F, 0.0F, true);
    EXPECT_EQ(trainMessage(oneClass, 2), "random forest: no outside samples");
    Set nan = oneClass;
    nan.add(std::numeric_limits<float>::quiet_NaN(), 0.0F, false);
    EXPECT_NE(trainMessage(nan, 2).find("not finite"), std::string::npos);
    Set good = oneClass;
    good.add(2.0F, 2.0F, false);
    EXPECT_NE(trainMessage(good, 3).find("feature values"), std::string::npos);
    ForestParams noTrees;
    noTrees.trees = 0;
    EXPECT_EQ(trainMessage(good, 2, noTrees), "random forest: trees must be in [1, 1024]");
    EXPECT_EQ(trainMessage(good, 2), "accepted");
}

} // namespace
} // namespace steerseg::test
