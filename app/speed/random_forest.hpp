#pragma once

// The classifier speed's forest (docs/speed.md): a random forest over per-voxel feature vectors,
// trained on the CPU from the operator's inside and outside examples and flattened for the GPU
// (shaders/speed/classifier_evaluate.comp walks the same nodes). GL-free.
#include <cstdint>
#include <span>
#include <vector>

namespace steerseg::speed {

struct ForestParams {
    int trees = 32;
    int maxDepth = 10;
    int minSamplesLeaf = 2;   // distinct samples a child must keep
    int featuresPerSplit = 0; // 0: the square root of the feature count, rounded up
    int thresholdBins = 32;   // candidate thresholds per feature and node: bin edges over its range
    std::uint32_t seed = 1;
    unsigned workers = 0; // threads that build the trees; 0: every core (the forest is the same)
};

// One node, 16 bytes in std430 order. A split sends sample[feature] < threshold to `left`, the
// rest to left + 1; a leaf has feature -1 and value P(inside) - P(outside) of its training
// samples, classes weighted to equal priors.
struct ForestNode {
    std::int32_t feature = -1;
    float threshold = 0.0F;
    std::int32_t left = 0;
    float value = 0.0F;
};
static_assert(sizeof(ForestNode) == 16);

class RandomForest {
  public:
    // features: one row of featureCount values per sample; labels: 1 inside, 0 outside. Each
    // class is weighted by the inverse of its count, so that the prediction does not lean to
    // the class with more examples. Deterministic for a seed. Throws std::invalid_argument when
    // a class is empty, the sizes disagree, a feature is not finite or a parameter is out of
    // range.
    static RandomForest train(std::span<const float> features, std::span<const std::uint8_t> labels,
                              int featureCount, const ForestParams& params = {});

    // P(inside) - P(outside) in [-1, 1]: the mean over the trees of the leaf reached, summed in
    // tree order in single precision as the GPU does.
    [[nodiscard]] float predict(std::span<const float> sample) const;

    [[nodiscard]] const std::vector<ForestNode>& nodes() const { return nodes_; }
    [[nodiscard]] const std::vector<std::int32_t>& roots() const { return roots_; }
    [[nodiscard]] int featureCount() const { return featureCount_; }
    // Balanced accuracy (the mean of the two classes' rates) of each sample's prediction by the
    // trees whose bootstrap left it out; NaN where no sample was left out.
    [[nodiscard]] double outOfBagAccuracy() const { return outOfBagAccuracy_; }

  private:
    std::vector<ForestNode> nodes_;
    std::vector<std::int32_t> roots_;
    int featureCount_ = 0;
    double outOfBagAccuracy_ = 0.0;
};

} // namespace steerseg::speed
