#include "speed/place_vote.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace steerseg::speed {

namespace {

constexpr float kMinRadius = 0.5F;

// The strongest weight of `marks` at every cell centre, into `strongest`.
void strongestWeights(std::span<const Example> marks, const glm::ivec3& cells, float reach,
                      const glm::vec3& scale, std::vector<float>& strongest) {
    const float cell = static_cast<float>(kPlaceVoteCell);
    for (const Example& m : marks) {
        if (!std::isfinite(m.centre.x) || !std::isfinite(m.centre.y) ||
            !std::isfinite(m.centre.z) || !std::isfinite(m.radius) || m.radius < 0.0F) {
            throw std::invalid_argument(
                "place vote: a mark's centre and radius must be finite, the radius >= 0");
        }
        const float extent = std::max(m.radius, kMinRadius) * std::max(reach, 1.0F);
        // The cells whose centres (voxel c * cell + (cell - 1) / 2) lie within the extent,
        // clamped to the grid in floats, so that a huge mark or one far away stays in range.
        auto cellRange = [&](float centre, int count, float step) {
            const float extentHere = extent / step;
            const float offset = (cell - 1.0F) * 0.5F;
            const float top = static_cast<float>(count - 1);
            const float lo =
                std::clamp(std::ceil((centre - extentHere - offset) / cell), 0.0F, top);
            const float hi =
                std::clamp(std::floor((centre + extentHere - offset) / cell), -1.0F, top);
            return glm::ivec2(static_cast<int>(lo), static_cast<int>(hi));
        };
        const glm::ivec2 rx = cellRange(m.centre.x, cells.x, scale.x);
        const glm::ivec2 ry = cellRange(m.centre.y, cells.y, scale.y);
        const glm::ivec2 rz = cellRange(m.centre.z, cells.z, scale.z);
        for (int z = rz.x; z <= rz.y; ++z) {
            for (int y = ry.x; y <= ry.y; ++y) {
                for (int x = rx.x; x <= rx.y; ++x) {
                    const glm::vec3 p = glm::vec3(x, y, z) * cell + (cell - 1.0F) * 0.5F;
                    const float w =
                        placeWeight(glm::length((p - m.centre) * scale), m.radius, reach);
                    const std::size_t i =
                        static_cast<std::size_t>(x) +
                        static_cast<std::size_t>(cells.x) *
                            (static_cast<std::size_t>(y) +
                             static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(z));
                    strongest[i] = std::max(strongest[i], w);
                }
            }
        }
    }
}

} // namespace

float placeWeight(float distance, float radius, float reach) {
    const float r = std::max(radius, kMinRadius);
    if (distance <= r) {
        return 1.0F;
    }
    if (reach <= 1.0F) {
        return 0.0F;
    }
    return std::max(0.0F, 1.0F - (distance - r) / ((reach - 1.0F) * r));
}

PlaceVote placeVote(std::span<const Example> inside, std::span<const Example> outside,
                    glm::ivec3 dims, float reach, const glm::vec3& scale) {
    if (dims.x < 1 || dims.y < 1 || dims.z < 1) {
        throw std::invalid_argument("place vote: the scan's dimensions must be at least 1");
    }
    if (!std::isfinite(reach) || reach < 0.0F) {
        throw std::invalid_argument("place vote: the reach must be finite and >= 0");
    }
    PlaceVote vote;
    vote.dims = (dims + kPlaceVoteCell - 1) / kPlaceVoteCell;
    const std::size_t n = static_cast<std::size_t>(vote.dims.x) *
                          static_cast<std::size_t>(vote.dims.y) *
                          static_cast<std::size_t>(vote.dims.z);
    std::vector<float> in(n, 0.0F);
    std::vector<float> out(n, 0.0F);
    if (reach > 0.0F) {
        strongestWeights(inside, vote.dims, reach, scale, in);
        strongestWeights(outside, vote.dims, reach, scale, out);
    }
    vote.values.resize(n);
    std::transform(in.begin(), in.end(), out.begin(), vote.values.begin(),
                   [](float a, float b) { return a - b; });
    return vote;
}

float placeVoteAt(const PlaceVote& vote, glm::ivec3 v) {
    const float cell = static_cast<float>(kPlaceVoteCell);
    // In cell units from the first cell's centre, clamped as the texture's edge is.
    const glm::vec3 at = glm::clamp((glm::vec3(v) - (cell - 1.0F) * 0.5F) / cell, glm::vec3(0.0F),
                                    glm::vec3(vote.dims - 1));
    const glm::ivec3 lo = glm::ivec3(glm::floor(at));
    const glm::ivec3 hi = glm::min(lo + 1, vote.dims - 1);
    const glm::vec3 t = at - glm::vec3(lo);
    auto value = [&](int x, int y, int z) {
        return vote
            .values[static_cast<std::size_t>(x) +
                    static_cast<std::size_t>(vote.dims.x) *
                        (static_cast<std::size_t>(y) +
                         static_cast<std::size_t>(vote.dims.y) * static_cast<std::size_t>(z))];
    };
    auto alongX = [&](int y, int z) { return glm::mix(value(lo.x, y, z), value(hi.x, y, z), t.x); };
    auto alongY = [&](int z) { return glm::mix(alongX(lo.y, z), alongX(hi.y, z), t.y); };
    return glm::mix(alongY(lo.z), alongY(hi.z), t.z);
}

} // namespace steerseg::speed
