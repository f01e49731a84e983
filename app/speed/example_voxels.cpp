#include "speed/example_voxels.hpp"

#include "core/volume.hpp"
#include "speed/split_mix.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::speed {

namespace {

bool contains(const Example& e, glm::ivec3 v, const glm::dvec3& scale) {
    const glm::dvec3 d = (glm::dvec3(v) - glm::dvec3(e.centre)) * scale;
    return glm::dot(d, d) <= static_cast<double>(e.radius) * static_cast<double>(e.radius);
}

} // namespace

ExampleVoxels exampleVoxels(std::span<const Example> examples, glm::ivec3 dims,
                            std::size_t maxSamples, std::uint64_t seed, std::string_view what,
                            const glm::vec3& scale) {
    const std::string name(what);
    if (examples.empty()) {
        throw std::invalid_argument("classifier speed: no " + name + " examples");
    }
    for (const Example& e : examples) {
        if (!std::isfinite(e.centre.x) || !std::isfinite(e.centre.y) ||
            !std::isfinite(e.centre.z) || !std::isfinite(e.radius) || e.radius < 0.0F) {
            throw std::invalid_argument("classifier speed: an " + name +
                                        " example's centre or radius is not a finite position "
                                        "and non-negative radius");
        }
    }
    if (dims.x < 1 || dims.y < 1 || dims.z < 1 || maxSamples == 0) {
        throw std::invalid_argument("classifier speed: empty scan " + dimsText(dims) +
                                    " or no samples allowed");
    }
    // Each sphere's box clipped to the scan, in double so that a huge radius cannot overflow;
    // empty boxes (hi < lo) for spheres beside the scan.
    std::vector<std::pair<glm::ivec3, glm::ivec3>> boxes;
    boxes.reserve(examples.size());
    glm::ivec3 unionLo = dims;
    glm::ivec3 unionHi(-1);
    for (const Example& e : examples) {
        glm::ivec3 lo;
        glm::ivec3 hi;
        for (int a = 0; a < 3; ++a) {
            const double c = static_cast<double>(e.centre[a]);
            const double r = static_cast<double>(e.radius) / static_cast<double>(scale[a]);
            lo[a] =
                static_cast<int>(std::clamp(std::ceil(c - r), 0.0, static_cast<double>(dims[a])));
            hi[a] = static_cast<int>(
                std::clamp(std::floor(c + r), -1.0, static_cast<double>(dims[a] - 1)));
        }
        boxes.emplace_back(lo, hi);
        if (glm::all(glm::lessThanEqual(lo, hi))) {
            unionLo = glm::min(unionLo, lo);
            unionHi = glm::max(unionHi, hi);
        }
    }
    // Overlapping spheres: a voxel counts for the first sphere holding it. One bit per voxel of
    // the spheres' common box, so the cost follows their volume however many there are (a
    // painted stroke brings thousands).
    const glm::ivec3 extent = glm::max(unionHi - unionLo + 1, glm::ivec3(0));
    std::vector<bool> seen(static_cast<std::size_t>(extent.x) * static_cast<std::size_t>(extent.y) *
                           static_cast<std::size_t>(extent.z));
    ExampleVoxels result;
    SplitMix rng(seed);
    for (std::size_t s = 0; s < examples.size(); ++s) {
        const Example& e = examples[s];
        const auto [lo, hi] = boxes[s];
        for (int k = lo.z; k <= hi.z; ++k) {
            for (int j = lo.y; j <= hi.y; ++j) {
                for (int i = lo.x; i <= hi.x; ++i) {
                    const glm::ivec3 v(i, j, k);
                    if (!contains(e, v, glm::dvec3(scale))) {
                        continue;
                    }
                    const glm::ivec3 d = v - unionLo;
                    const std::size_t bit =
                        static_cast<std::size_t>(d.x) +
                        static_cast<std::size_t>(extent.x) *
                            (static_cast<std::size_t>(d.y) +
                             static_cast<std::size_t>(extent.y) * static_cast<std::size_t>(d.z));
                    if (seen[bit]) {
                        continue;
                    }
                    seen[bit] = true;
                    if (result.voxels.size() < maxSamples) {
                        result.voxels.push_back(v);
                    } else {
                        const std::uint64_t slot = rng.below(result.covered + 1);
                        if (slot < maxSamples) {
                            result.voxels[slot] = v;
                        }
                    }
                    ++result.covered;
                }
            }
        }
    }
    if (result.covered == 0) {
        throw std::invalid_argument("classifier speed: the " + name +
                                    " examples cover no voxel of the scan (" + dimsText(dims) +
                                    ")");
    }
    std::sort(result.voxels.begin(), result.voxels.end(), [](glm::ivec3 a, glm::ivec3 b) {
        return a.z != b.z ? a.z < b.z : (a.y != b.y ? a.y < b.y : a.x < b.x);
    });
    return result;
}

} // namespace steerseg::speed
