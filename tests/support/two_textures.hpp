#pragma once

// The classifier's test case (issue 13): two textures of one mean intensity, 100, with uniform
// noise of amplitude 8 for i < borderX (calm) and 40 beyond (rough), i fastest. A linear
// congruential generator from `seed`, so the same numbers on every platform.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace steerseg::test {

std::vector<float> twoTextureIntensities(const glm::ivec3& dims, int borderX, std::uint32_t seed);

} // namespace steerseg::test
