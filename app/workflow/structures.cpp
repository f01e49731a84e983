#include "workflow/structures.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace steerseg::workflow {

std::optional<std::size_t> StructureList::find(std::string_view name) const {
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].info.name == name) {
            return i;
        }
    }
    return std::nullopt;
}

MaskRuns claimedBy(const StructureList& list, std::size_t except, std::size_t voxels) {
    // The inside intervals of every mask, merged: runs alternate outside, inside, ...
    std::vector<std::pair<std::uint64_t, std::uint64_t>> inside;
    for (std::size_t s = 0; s < list.items.size(); ++s) {
        const MaskRuns& m = list.items[s].mask;
        if (s == except || m.runs.empty()) {
            continue;
        }
        std::uint64_t at = 0;
        for (std::size_t r = 0; r < m.runs.size(); ++r) {
            const std::uint64_t end = at + m.runs[r];
            if (r % 2 == 1 && end > at) {
                inside.emplace_back(at, end);
            }
            at = end;
        }
    }
    MaskRuns out;
    if (inside.empty()) {
        return out;
    }
    std::sort(inside.begin(), inside.end());
    out.voxels = voxels;
    std::uint64_t covered = 0; // everything before it is written
    std::uint64_t lo = inside.front().first;
    std::uint64_t hi = inside.front().second;
    // A run longer than 32 bits goes as several, a zero-length run of the other kind between.
    const auto run = [&](std::uint64_t length) {
        constexpr std::uint64_t kMost = 0xFFFFFFFFU;
        while (length > kMost) {
            out.runs.push_back(static_cast<std::uint32_t>(kMost));
            out.runs.push_back(0);
            length -= kMost;
        }
        out.runs.push_back(static_cast<std::uint32_t>(length));
    };
    const auto emit = [&](std::uint64_t a, std::uint64_t b) {
        run(a - covered);
        run(b - a);
        covered = b;
    };
    for (const auto& [a, b] : inside) {
        if (a > hi) {
            emit(lo, hi);
            lo = a;
            hi = b;
        } else {
            hi = std::max(hi, b);
        }
    }
    emit(lo, hi);
    if (covered < voxels) {
        run(voxels - covered);
    }
    return out;
}

} // namespace steerseg::workflow
