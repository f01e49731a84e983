#include "speed/random_forest.hpp"

#include "core/parallel_for.hpp"
#include "speed/split_mix.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace steerseg::speed {

namespace {

struct Split {
    int feature = -1;
    float threshold = 0.0F;
    double cost = std::numeric_limits<double>::infinity();
};

// Gini impurity times weight, 2 a b / (a + b), for class weights a and b.
double giniCost(double a, double b) {
    const double w = a + b;
    return w > 0.0 ? 2.0 * a * b / w : 0.0;
}

void checkParams(const ForestParams& p, int featureCount) {
    auto require = [](bool ok, const std::string& what) {
        if (!ok) {
            throw std::invalid_argument("random forest: " + what);
        }
    };
    require(featureCount >= 1, "the feature count must be at least 1");
    require(p.trees >= 1 && p.trees <= 1024, "trees must be in [1, 1024]");
    require(p.maxDepth >= 1 && p.maxDepth <= 24, "the depth must be in [1, 24]");
    require(p.minSamplesLeaf >= 1, "the samples per leaf must be at least 1");
    require(p.featuresPerSplit >= 0 && p.featuresPerSplit <= featureCount,
            "the features per split must be in [0, the feature count]");
    require(p.thresholdBins >= 2 && p.thresholdBins <= 4096,
            "the threshold bins must be in [2, 4096]");
}

// One tree's training: its bootstrap's sample indices are partitioned in place as nodes split.
class TreeBuilder {
  public:
    TreeBuilder(std::span<const float> features, std::span<const double> weights,
                std::span<const std::uint8_t> labels, int featureCount, const ForestParams& params,
                SplitMix& rng, std::vector<ForestNode>& nodes)
        : features_(features), weights_(weights), labels_(labels), featureCount_(featureCount),
          params_(params), rng_(rng), nodes_(nodes),
          featureOrder_(static_cast<std::size_t>(featureCount)),
          binIn_(static_cast<std::size_t>(params.thresholdBins)),
          binOut_(static_cast<std::size_t>(params.thresholdBins)),
          binCount_(static_cast<std::size_t>(params.thresholdBins)) {
        splitFeatures_ = params.featuresPerSplit > 0
                             ? params.featuresPerSplit
                             : static_cast<int>(std::ceil(std::sqrt(featureCount)));
    }

    // Builds the node at nodes_[at] over samples [begin, end).
    void build(std::size_t at, std::vector<std::uint32_t>& samples, std::size_t begin,
               std::size_t end, int depth) {
        double in = 0.0;
        double out = 0.0;
        for (std::size_t s = begin; s < end; ++s) {
            (labels_[samples[s]] != 0 ? in : out) += weights_[samples[s]];
        }
        nodes_[at] = ForestNode{-1, 0.0F, 0, static_cast<float>((in - out) / (in + out))};
        const auto minLeaf = static_cast<std::size_t>(params_.minSamplesLeaf);
        if (depth >= params_.maxDepth || in == 0.0 || out == 0.0 || end - begin < 2 * minLeaf) {
            return;
        }
        const Split split = bestSplit(samples, begin, end, giniCost(in, out));
        if (split.feature < 0) {
            return;
        }
        const auto mid = static_cast<std::size_t>(
            std::partition(
                samples.begin() + static_cast<std::ptrdiff_t>(begin),
                samples.begin() + static_cast<std::ptrdiff_t>(end),
                [&](std::uint32_t s) { return value(s, split.feature) < split.threshold; }) -
            samples.begin());
        if (mid == begin || mid == end) {
            return; // the bin edge fell on a rounding boundary: keep the leaf
        }
        const auto left = static_cast<std::int32_t>(nodes_.size());
        nodes_[at].feature = split.feature;
        nodes_[at].threshold = split.threshold;
        nodes_[at].left = left;
        nodes_.resize(nodes_.size() + 2);
        build(static_cast<std::size_t>(left), samples, begin, mid, depth + 1);
        build(static_cast<std::size_t>(left) + 1, samples, mid, end, depth + 1);
    }

  private:
    [[nodiscard]] float value(std::uint32_t sample, int feature) const {
        return features_[static_cast<std::size_t>(sample) *
                             static_cast<std::size_t>(featureCount_) +
                         static_cast<std::size_t>(feature)];
    }

    Split bestSplit(const std::vector<std::uint32_t>& samples, std::size_t begin, std::size_t end,
                    double parentCost) {
        // A random subset of the features (a partial Fisher-Yates shuffle).
        std::iota(featureOrder_.begin(), featureOrder_.end(), 0);
        Split best;
        const auto bins = static_cast<std::size_t>(params_.thresholdBins);
        const auto minLeaf = static_cast<std::size_t>(params_.minSamplesLeaf);
        for (int n = 0; n < splitFeatures_; ++n) {
            const auto pick = static_cast<std::size_t>(n) +
                              rng_.below(static_cast<std::uint64_t>(featureCount_ - n));
            std::swap(featureOrder_[static_cast<std::size_t>(n)], featureOrder_[pick]);
            const int feature = featureOrder_[static_cast<std::size_t>(n)];
            float lo = std::numeric_limits<float>::infinity();
            float hi = -lo;
            for (std::size_t s = begin; s < end; ++s) {
                const float v = value(samples[s], feature);
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
            if (!(hi > lo)) {
                continue;
            }
            const double low = static_cast<double>(lo);
            const double range = static_cast<double>(hi) - low;
            // Class weights per bin of equal width over the node's range; candidate thresholds
            // are the bins' inner edges: O(samples + bins) per feature instead of a sort.
            std::fill(binIn_.begin(), binIn_.end(), 0.0);
            std::fill(binOut_.begin(), binOut_.end(), 0.0);
            std::fill(binCount_.begin(), binCount_.end(), std::size_t{0});
            const double scale = static_cast<double>(bins) / range;
            for (std::size_t s = begin; s < end; ++s) {
                const std::uint32_t sample = samples[s];
                const auto b = std::min(
                    bins - 1, static_cast<std::size_t>(
                                  (static_cast<double>(value(sample, feature)) - low) * scale));
                (labels_[sample] != 0 ? binIn_ : binOut_)[b] += weights_[sample];
                ++binCount_[b];
            }
            double totalIn = 0.0;
            double totalOut = 0.0;
            for (std::size_t b = 0; b < bins; ++b) {
                totalIn += binIn_[b];
                totalOut += binOut_[b];
            }
            double leftIn = 0.0;
            double leftOut = 0.0;
            std::size_t leftCount = 0;
            const std::size_t count = end - begin;
            for (std::size_t b = 0; b + 1 < bins; ++b) {
                leftIn += binIn_[b];
                leftOut += binOut_[b];
                leftCount += binCount_[b];
                if (leftCount < minLeaf || count - leftCount < minLeaf) {
                    continue;
                }
                const double cost =
                    giniCost(leftIn, leftOut) + giniCost(totalIn - leftIn, totalOut - leftOut);
                if (cost < best.cost && cost < parentCost * (1.0 - 1e-9)) {
                    best.cost = cost;
                    best.feature = feature;
                    best.threshold = static_cast<float>(low + static_cast<double>(b + 1) * range /
                                                                  static_cast<double>(bins));
                }
            }
        }
        return best;
    }

    std::span<const float> features_;
    std::span<const double> weights_;
    std::span<const std::uint8_t> labels_;
    int featureCount_;
    const ForestParams& params_;
    SplitMix& rng_;
    std::vector<ForestNode>& nodes_;
    std::vector<int> featureOrder_;
    int splitFeatures_ = 1;
    std::vector<double> binIn_;
    std::vector<double> binOut_;
    std::vector<std::size_t> binCount_;
};

float walk(const std::vector<ForestNode>& nodes, std::int32_t root, std::span<const float> sample) {
    std::int32_t n = root;
    while (nodes[static_cast<std::size_t>(n)].feature >= 0) {
        const ForestNode& node = nodes[static_cast<std::size_t>(n)];
        n = node.left + (sample[static_cast<std::size_t>(node.feature)] < node.threshold ? 0 : 1);
    }
    return nodes[static_cast<std::size_t>(n)].value;
}

} // namespace

RandomForest RandomForest::train(std::span<const float> features,
                                 std::span<const std::uint8_t> labels, int featureCount,
                                 const ForestParams& params) {
    checkParams(params, featureCount);
    const std::size_t count = labels.size();
    if (features.size() != count * static_cast<std::size_t>(featureCount)) {
        throw std::invalid_argument("random forest: " + std::to_string(features.size()) +
                                    " feature values for " + std::to_string(count) +
                                    " samples of " + std::to_string(featureCount));
    }
    if (count > std::numeric_limits<std::uint32_t>::max()) {
        throw std::invalid_argument("random forest: too many samples");
    }
    if (!std::all_of(features.begin(), features.end(), [](float v) { return std::isfinite(v); })) {
        throw std::invalid_argument(
            "random forest: a training sample's features are not finite (NaN or infinite "
            "intensities near the examples)");
    }
    const auto inside = static_cast<std::size_t>(
        std::count_if(labels.begin(), labels.end(), [](std::uint8_t l) { return l != 0; }));
    if (inside == 0 || inside == count) {
        throw std::invalid_argument(std::string("random forest: no ") +
                                    (inside == 0 ? "inside" : "outside") + " samples");
    }
    // Equal priors: each class weighs one half, however many samples it has.
    std::vector<double> unitWeight(count);
    for (std::size_t s = 0; s < count; ++s) {
        unitWeight[s] = 0.5 / static_cast<double>(labels[s] != 0 ? inside : count - inside);
    }

    // Each tree draws from its own seed, so the trees are built apart, on every core (a
    // correction's retraining is in the frame before its edit shows), and laid out in tree order
    // as one thread would: the same forest for any number of workers.
    const auto trees = static_cast<std::size_t>(params.trees);
    std::vector<std::vector<ForestNode>> treeNodes(trees);
    std::vector<std::vector<bool>> outOfBag(trees);
    std::atomic<std::size_t> nextTree{0};
    const unsigned workers = parallelWorkers(trees, params.workers);
    parallelFor(
        workers,
        [&](std::size_t) {
            std::vector<std::uint32_t> drawn(count);
            std::vector<double> weights(count);
            std::vector<std::uint32_t> samples;
            for (std::size_t t = nextTree++; t < trees; t = nextTree++) {
                SplitMix rng(static_cast<std::uint64_t>(params.seed) * 0x100000001B3ULL +
                             static_cast<std::uint64_t>(t));
                std::fill(drawn.begin(), drawn.end(), 0U);
                for (std::size_t n = 0; n < count; ++n) {
                    ++drawn[rng.below(count)];
                }
                // A sample drawn k times weighs k times: the bootstrap without duplicate rows.
                samples.clear();
                std::vector<bool>& unused = outOfBag[t];
                unused.assign(count, false);
                for (std::size_t s = 0; s < count; ++s) {
                    weights[s] = unitWeight[s] * drawn[s];
                    if (drawn[s] > 0) {
                        samples.push_back(static_cast<std::uint32_t>(s));
                    } else {
                        unused[s] = true;
                    }
                }
                std::vector<ForestNode>& nodes = treeNodes[t];
                nodes.emplace_back();
                const bool bothClasses =
                    std::any_of(samples.begin(), samples.end(),
                                [&](std::uint32_t s) { return labels[s] != 0; }) &&
                    std::any_of(samples.begin(), samples.end(),
                                [&](std::uint32_t s) { return labels[s] == 0; });
                if (bothClasses) {
                    TreeBuilder builder(features, weights, labels, featureCount, params, rng,
                                        nodes);
                    builder.build(0, samples, 0, samples.size(), 0);
                }
                // else a bootstrap of one class (tiny sets only) says nothing: a neutral leaf.
            }
        },
        workers);

    RandomForest forest;
    forest.featureCount_ = featureCount;
    for (const std::vector<ForestNode>& nodes : treeNodes) {
        const auto root = static_cast<std::int32_t>(forest.nodes_.size());
        forest.roots_.push_back(root);
        for (ForestNode node : nodes) {
            node.left += node.feature >= 0 ? root : 0;
            forest.nodes_.push_back(node);
        }
    }
    // Each sample's out-of-bag votes summed in tree order, as the trees were built one by one.
    std::vector<float> oobSum(count, 0.0F);
    std::vector<int> oobTrees(count, 0);
    constexpr std::size_t kOobChunk = 4096;
    parallelFor((count + kOobChunk - 1) / kOobChunk,
                [&](std::size_t chunk) {
                    const std::size_t end = std::min(count, (chunk + 1) * kOobChunk);
                    for (std::size_t s = chunk * kOobChunk; s < end; ++s) {
                        for (std::size_t t = 0; t < trees; ++t) {
                            if (outOfBag[t][s]) {
                                oobSum[s] += walk(
                                    forest.nodes_, forest.roots_[t],
                                    features.subspan(s * static_cast<std::size_t>(featureCount),
                                                     static_cast<std::size_t>(featureCount)));
                                ++oobTrees[s];
                            }
                        }
                    }
                },
                params.workers);

    std::array<std::size_t, 2> seen{};
    std::array<std::size_t, 2> right{};
    for (std::size_t s = 0; s < count; ++s) {
        if (oobTrees[s] > 0) {
            const std::size_t c = labels[s] != 0 ? 1 : 0;
            ++seen[c];
            right[c] += ((oobSum[s] > 0.0F) == (c == 1)) ? 1 : 0;
        }
    }
    forest.outOfBagAccuracy_ =
        seen[0] > 0 && seen[1] > 0
            ? 0.5 * (static_cast<double>(right[0]) / static_cast<double>(seen[0]) +
                     static_cast<double>(right[1]) / static_cast<double>(seen[1]))
            : std::numeric_limits<double>::quiet_NaN();
    return forest;
}

float RandomForest::predict(std::span<const float> sample) const {
    if (sample.size() != static_cast<std::size_t>(featureCount_)) {
        throw std::invalid_argument("random forest: a sample of " + std::to_string(sample.size()) +
                                    " features for a forest of " + std::to_string(featureCount_));
    }
    float sum = 0.0F;
    for (const std::int32_t root : roots_) {
        sum += walk(nodes_, root, sample);
    }
    return sum / static_cast<float>(roots_.size());
}

} // namespace steerseg::speed
