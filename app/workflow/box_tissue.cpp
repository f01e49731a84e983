#include "workflow/box_tissue.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace steerseg::workflow {

model::Box innerBox(const model::Box& box) {
    const glm::ivec3 quarter = model::sizeOf(box) / 4;
    return {box.lo + quarter, glm::max(box.hi - quarter, box.lo + quarter)};
}

std::optional<TissuePeak> dominantTissue(std::vector<double> values) {
    std::erase_if(values, [](double v) { return !std::isfinite(v); });
    if (values.empty()) {
        return std::nullopt;
    }
    if (values.size() < kMinTissueValues) {
        // Too few for a histogram (a box of a few voxels): they are the tissue.
        double sum = 0.0;
        double squares = 0.0;
        for (const double v : values) {
            sum += v;
            squares += v * v;
        }
        const double n = static_cast<double>(values.size());
        const double mean = sum / n;
        return TissuePeak{mean, std::sqrt(std::max(squares / n - mean * mean, 0.0))};
    }
    std::sort(values.begin(), values.end());
    const auto at = [&values](double q) {
        return values[static_cast<std::size_t>(q * static_cast<double>(values.size() - 1))];
    };
    const double lo = at(0.01);
    const double hi = at(0.99);
    if (!(hi > lo)) {
        return TissuePeak{lo, 0.0}; // one value fills the box
    }
    const double width = (hi - lo) / kTissueBins;
    std::array<double, kTissueBins> counts{};
    for (const double v : values) {
        if (v >= lo && v <= hi) {
            const int b = std::min(static_cast<int>((v - lo) / width), kTissueBins - 1);
            counts[static_cast<std::size_t>(b)] += 1.0;
        }
    }
    // One [1 2 1] pass: a peak split across a bin edge counts as one.
    std::array<double, kTissueBins> smooth{};
    for (int b = 0; b < kTissueBins; ++b) {
        const double left = counts[static_cast<std::size_t>(std::max(b - 1, 0))];
        const double right = counts[static_cast<std::size_t>(std::min(b + 1, kTissueBins - 1))];
        smooth[static_cast<std::size_t>(b)] =
            0.25 * left + 0.5 * counts[static_cast<std::size_t>(b)] + 0.25 * right;
    }
    const auto peak =
        static_cast<int>(std::max_element(smooth.begin(), smooth.end()) - smooth.begin());
    const double half = 0.5 * smooth[static_cast<std::size_t>(peak)];
    int left = peak;
    while (left > 0 && smooth[static_cast<std::size_t>(left - 1)] >= half) {
        --left;
    }
    int right = peak;
    while (right < kTissueBins - 1 && smooth[static_cast<std::size_t>(right + 1)] >= half) {
        ++right;
    }
    const double from = lo + width * left;
    const double to = lo + width * (right + 1);
    double sum = 0.0;
    std::size_t n = 0;
    for (const double v : values) {
        if (v >= from && v <= to) {
            sum += v;
            ++n;
        }
    }
    // A normal's half width at half maximum is sqrt(2 ln 2) = 1.1774 standard deviations.
    return TissuePeak{n > 0 ? sum / static_cast<double>(n) : 0.5 * (from + to),
                      0.5 * (to - from) / 1.1774};
}

} // namespace steerseg::workflow
