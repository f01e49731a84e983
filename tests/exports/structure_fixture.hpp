#pragma once

// Three structures on a 24 x 20 x 10 grid for the several-structure export tests: a box
// ("Liver"), a ball ("Spleen") and a box ("Left kidney") that either keeps clear of the ball or
// cuts into it. Slices 0 and 9 hold none of them; every structure misses some slices.
#include "exports/structure_export.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace steerseg::test {

inline constexpr glm::ivec3 kStructureDims{24, 20, 10};

struct StructureMasks {
    std::vector<std::uint8_t> liver;
    std::vector<std::uint8_t> spleen;
    std::vector<std::uint8_t> kidney;
};

inline StructureMasks structureMasks(const glm::ivec3& dims, bool overlapping) {
    const std::size_t n = static_cast<std::size_t>(dims.x) * dims.y * dims.z;
    StructureMasks m{std::vector<std::uint8_t>(n), std::vector<std::uint8_t>(n),
                     std::vector<std::uint8_t>(n)};
    const int kidneyJ0 = overlapping ? 8 : 12;
    const int kidneyK0 = overlapping ? 3 : 5;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                const std::size_t v = linearIndex(dims, i, j, k);
                // Values other than 1 inside: any non-zero counts.
                m.liver[v] = i >= 2 && i <= 9 && j >= 2 && j <= 15 && k >= 1 && k <= 6 ? 1 : 0;
                const glm::dvec3 d = glm::dvec3(i, j, k) - glm::dvec3(16, 6, 4);
                m.spleen[v] = glm::dot(d, d) <= 3.5 * 3.5 ? 255 : 0;
                m.kidney[v] =
                    i >= 13 && i <= 21 && j >= kidneyJ0 && j <= 17 && k >= kidneyK0 && k <= 8 ? 7
                                                                                              : 0;
            }
        }
    }
    return m;
}

// Names, label values 1..3, colours and codes of the three.
inline std::vector<exports::StructureLayer> structureLayers(const StructureMasks& m) {
    std::vector<exports::StructureLayer> out(3);
    const exports::SegmentCode organ{"123037004", "SCT", "Anatomical Structure"};
    out[0].segment.name = "Liver";
    out[0].segment.color = {0.8, 0.3, 0.2};
    out[0].segment.label = 1;
    out[0].category = organ;
    out[0].type = {"10200004", "SCT", "Liver"};
    out[0].mask = m.liver;
    out[1].segment.name = "Spleen";
    out[1].segment.color = {0.2, 0.6, 0.9};
    out[1].segment.label = 2;
    out[1].category = organ;
    out[1].type = {"78961009", "SCT", "Spleen"};
    out[1].mask = m.spleen;
    out[2].segment.name = "Left kidney";
    out[2].segment.color = {1.0, 0.85, 0.1};
    out[2].segment.label = 3;
    out[2].category = organ;
    out[2].type = {"64033007", "SCT", "Kidney"};
    out[2].mask = m.kidney;
    return out;
}

} // namespace steerseg::test
