#include "speed/classifier_speed_cpu.hpp"

#include "speed/classifier_features_cpu.hpp"

#include <cmath>
#include <stdexcept>

namespace steerseg::speed {

float classifierSpeedFrom(float look, float place) {
    return look + (1.0F - std::abs(look)) * place;
}

std::vector<float> cpuClassifierSpeed(const RandomForest& forest, const PlaceVote& vote,
                                      std::span<const float> features,
                                      std::span<const glm::ivec3> voxels) {
    constexpr auto row = static_cast<std::size_t>(kClassifierFeatureCount);
    if (features.size() != voxels.size() * row) {
        throw std::invalid_argument("classifier speed: one feature row per voxel is needed");
    }
    std::vector<float> out(voxels.size());
    for (std::size_t n = 0; n < voxels.size(); ++n) {
        out[n] = classifierSpeedFrom(forest.predict(features.subspan(n * row, row)),
                                     placeVoteAt(vote, voxels[n]));
    }
    return out;
}

} // namespace steerseg::speed
