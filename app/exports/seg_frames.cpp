// The SEG's frame layout (seg_frames.hpp), DCMTK-free so that its bits can be tested alone.
#include "exports/seg_frames.hpp"

#include <algorithm>

namespace steerseg::exports {

std::vector<int> segmentedSlices(const Geometry& g, std::span<const std::uint8_t> mask) {
    const std::size_t plane =
        static_cast<std::size_t>(g.dims.x) * static_cast<std::size_t>(g.dims.y);
    std::vector<int> slices;
    for (int k = 0; k < g.dims.z; ++k) {
        const auto slab = mask.subspan(static_cast<std::size_t>(k) * plane, plane);
        if (std::any_of(slab.begin(), slab.end(), [](std::uint8_t v) { return v != 0; })) {
            slices.push_back(k);
        }
    }
    return slices;
}

std::vector<std::uint8_t> packFrames(const Geometry& g, std::span<const DicomSegment> segments,
                                     const std::vector<Frame>& frames) {
    const std::size_t plane =
        static_cast<std::size_t>(g.dims.x) * static_cast<std::size_t>(g.dims.y);
    const std::size_t bits = plane * frames.size();
    std::vector<std::uint8_t> packed((bits + 15) / 16 * 2, 0);
    std::size_t bit = 0;
    for (const Frame& f : frames) {
        const auto slab =
            segments[f.segment].mask.subspan(static_cast<std::size_t>(f.k) * plane, plane);
        for (const std::uint8_t v : slab) {
            if (v != 0) {
                packed[bit / 8] = static_cast<std::uint8_t>(packed[bit / 8] | (1U << (bit % 8)));
            }
            ++bit;
        }
    }
    return packed;
}

} // namespace steerseg::exports
