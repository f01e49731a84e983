#include "speed/classifier_speed_cpu.hpp"

#include "speed/classifier_features_cpu.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::speed {

float classifierSpeedFrom(float look, float place) {
    return look + (1.0F - std::abs(look)) * place;
}

std::vector<float> cpuForestLooks(const RandomForest& forest, std::span<const float> features) {
    constexpr auto row = static_cast<std::size_t>(kClassifierFeatureCount);
    if (features.size() % row != 0) {
        throw std::invalid_argument("classifier speed: feature rows of " + std::to_string(row) +
                                    " values each");
    }
    std::vector<float> looks(features.size() / row);
    for (std::size_t n = 0; n < looks.size(); ++n) {
        looks[n] = forest.predict(features.subspan(n * row, row));
    }
    return looks;
}

std::vector<float> cpuClassifierSpeed(const RandomForest& forest, const PlaceVote& vote,
                                      std::span<const float> features,
                                      std::span<const glm::ivec3> voxels) {
    if (features.size() != voxels.size() * static_cast<std::size_t>(kClassifierFeatureCount)) {
        throw std::invalid_argument("classifier speed: one feature row per voxel is needed");
    }
    std::vector<float> out = cpuForestLooks(forest, features);
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        out[n] = classifierSpeedFrom(out[n], placeVoteAt(vote, voxels[n]));
    }
    return out;
}

} // namespace steerseg::speed
