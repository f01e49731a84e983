#include "render/transfer_function.hpp"

#include "render/render_params.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace steerseg::render {

namespace {

// Real-unit intensity at a histogram quantile; the histogram spans [min, max].
double quantile(const IntensityStats& stats, double q) {
    std::uint64_t total = 0;
    for (auto n : stats.histogram) {
        total += n;
    }
    if (total == 0 || stats.histogram.empty()) {
        return stats.min + q * (stats.max - stats.min);
    }
    const auto wanted = static_cast<std::uint64_t>(q * static_cast<double>(total));
    std::uint64_t seen = 0;
    for (std::size_t b = 0; b < stats.histogram.size(); ++b) {
        seen += stats.histogram[b];
        if (seen > wanted) {
            const double f =
                (static_cast<double>(b) + 0.5) / static_cast<double>(stats.histogram.size());
            return stats.min + f * (stats.max - stats.min);
        }
    }
    return stats.max;
}

std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

} // namespace

TransferFunction transferPreset(TfPreset which, const IntensityStats& stats) {
    TransferFunction tf;
    switch (which) {
    case TfPreset::CtBone:
        tf.widgets.push_back({900.0, 700.0, 0.05, {0.95, 0.92, 0.85}, 0.8});
        break;
    case TfPreset::CtSoftTissue:
        tf.widgets.push_back({40.0, 120.0, 0.1, {0.85, 0.45, 0.35}, 0.08});
        tf.widgets.push_back({900.0, 700.0, 0.05, {0.95, 0.92, 0.85}, 0.6});
        break;
    case TfPreset::Mr: {
        // MR has no absolute scale: a faint shell over the tissue boundaries (gradient-gated
        // tent across the foreground above the background's tenth of the range) and the
        // brightest tail opaque.
        const double span = stats.max - stats.min;
        const double fgLow = stats.min + 0.1 * span;
        const double fgHigh = quantile(stats, 0.99);
        const double high = quantile(stats, 0.999);
        const double centre = 0.5 * (fgLow + std::max(fgLow, fgHigh));
        tf.widgets.push_back({centre,
                              std::max(0.6 * (fgHigh - fgLow), 0.05 * span),
                              0.15,
                              {0.85, 0.75, 0.65},
                              0.12});
        tf.widgets.push_back({high, std::max(1e-6, 0.15 * span), 0.0, {1.0, 0.95, 0.85}, 0.5});
        break;
    }
    }
    return tf;
}

WindowLevel windowPreset(TfPreset which, const IntensityStats& stats) {
    switch (which) {
    case TfPreset::CtBone:
        return {500.0, 2000.0};
    case TfPreset::CtSoftTissue:
        return {40.0, 400.0};
    case TfPreset::Mr:
        break;
    }
    const double lo = quantile(stats, 0.01);
    const double hi = quantile(stats, 0.999);
    return {0.5 * (lo + hi), std::max(1e-6, hi - lo)};
}

TfPreset parseTfPreset(const std::string& name) {
    if (name == "bone") {
        return TfPreset::CtBone;
    }
    if (name == "soft") {
        return TfPreset::CtSoftTissue;
    }
    if (name == "mr") {
        return TfPreset::Mr;
    }
    throw std::invalid_argument("unknown preset '" + name + "' (expected bone, soft or mr)");
}

std::vector<std::uint8_t> bakeTransferLut(const TransferFunction& tf, double rangeMin,
                                          double rangeMax) {
    std::vector<std::uint8_t> lut(static_cast<std::size_t>(kTfIntensityBins) * kTfGradientBins * 4);
    const double span = rangeMax > rangeMin ? rangeMax - rangeMin : 1.0;
    for (int g = 0; g < kTfGradientBins; ++g) {
        const double grad = static_cast<double>(g) / (kTfGradientBins - 1);
        for (int b = 0; b < kTfIntensityBins; ++b) {
            const double value = rangeMin + span * b / (kTfIntensityBins - 1);
            double r = 0.0;
            double gr = 0.0;
            double bl = 0.0;
            double a = 0.0;
            for (const TfWidget& w : tf.widgets) {
                const double tent =
                    std::max(0.0, 1.0 - std::abs(value - w.centre) / std::max(w.halfWidth, 1e-9));
                const double ramp =
                    w.minGradient <= 0.0
                        ? 1.0
                        : std::clamp((grad - w.minGradient) / std::max(0.05, w.minGradient), 0.0,
                                     1.0);
                const double wa = tent * ramp * w.opacity;
                r += wa * w.colour[0];
                gr += wa * w.colour[1];
                bl += wa * w.colour[2];
                a += wa;
            }
            const std::size_t at =
                4 * (static_cast<std::size_t>(g) * kTfIntensityBins + static_cast<std::size_t>(b));
            const double inv = a > 0.0 ? 1.0 / a : 0.0;
            lut[at] = toByte(r * inv);
            lut[at + 1] = toByte(gr * inv);
            lut[at + 2] = toByte(bl * inv);
            lut[at + 3] = toByte(a);
        }
    }
    return lut;
}

std::vector<float> occupancyTable(const std::vector<std::uint8_t>& lut) {
    constexpr std::size_t width = kTfIntensityBins + 1;
    std::vector<float> table(width * (kTfGradientBins + 1), 0.0F);
    for (std::size_t g = 0; g < kTfGradientBins; ++g) {
        float row = 0.0F; // occupied texels of gradient bin g below intensity bin b
        for (std::size_t b = 0; b < kTfIntensityBins; ++b) {
            row += lut[4 * (g * kTfIntensityBins + b) + 3] != 0 ? 1.0F : 0.0F;
            table[(g + 1) * width + b + 1] = table[g * width + b + 1] + row;
        }
    }
    return table;
}

bool occupiedIn(const std::vector<float>& table, int lo, int hi, int gHi) {
    // The same two lookups as blockOccupied() in shaders/render/raycast.comp.
    const std::size_t row = static_cast<std::size_t>(gHi + 1) * (kTfIntensityBins + 1);
    return table[row + static_cast<std::size_t>(hi) + 1] -
               table[row + static_cast<std::size_t>(lo)] >
           0.5F;
}

} // namespace steerseg::render
