#include "support/two_textures.hpp"

namespace steerseg::test {

std::vector<float> twoTextureIntensities(const glm::ivec3& dims, int borderX, std::uint32_t seed) {
    std::vector<float> v(static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                         static_cast<std::size_t>(dims.z));
    std::uint32_t state = seed;
    for (std::size_t n = 0; n < v.size(); ++n) {
        state = state * 1664525U + 1013904223U;
        const float u = static_cast<float>(state >> 8U) / 8388608.0F - 1.0F;
        const bool calm = static_cast<int>(n % static_cast<std::size_t>(dims.x)) < borderX;
        v[n] = 100.0F + (calm ? 8.0F : 40.0F) * u;
    }
    return v;
}

} // namespace steerseg::test
