#pragma once

#include "core/volume.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace steerseg::render {

// One region of the 2D transfer function (Kniss-style widget): a tent over intensity (real
// units) times a ramp over gradient magnitude, with a colour and a peak opacity.
struct TfWidget {
    double centre = 0.0;      // real units
    double halfWidth = 1.0;   // real units; opacity falls to 0 at centre +/- halfWidth
    double minGradient = 0.0; // [0, 1] of the gradient axis; below it the widget is clear
    std::array<double, 3> colour{1.0, 1.0, 1.0};
    double opacity = 0.5; // per millimetre of ray at the widget's peak
};

// The 2D transfer function over intensity x gradient magnitude. The gradient axis is the
// magnitude of the normalised intensity's gradient per voxel, divided by `gradientScale`.
struct TransferFunction {
    std::vector<TfWidget> widgets;
    double gradientScale = 0.15;
};

enum class TfPreset { CtBone, CtSoftTissue, Mr };

// Presets: CT ones in Hounsfield units; MR from the scan's own intensity distribution.
TransferFunction transferPreset(TfPreset which, const IntensityStats& stats);
struct WindowLevel;
WindowLevel windowPreset(TfPreset which, const IntensityStats& stats);
TfPreset parseTfPreset(const std::string& name); // "bone", "soft", "mr"

inline constexpr int kTfIntensityBins = 256;
inline constexpr int kTfGradientBins = 32;

// RGBA8 lookup table, intensity fastest: kTfIntensityBins x kTfGradientBins texels, intensity
// bin b covers normalised intensity b / (bins - 1) of [rangeMin, rangeMax]. Colour is
// premultiplied by nothing; alpha is opacity per millimetre scaled to 8 bits.
std::vector<std::uint8_t> bakeTransferLut(const TransferFunction& tf, double rangeMin,
                                          double rangeMax);

// Empty-space skipping: a summed-area table of the lut's texels with non-zero opacity,
// (kTfIntensityBins + 1) x (kTfGradientBins + 1) counts, intensity fastest: entry (b, g) counts
// the occupied texels of intensity bin < b and gradient bin < g. Whether any texel of intensity
// bins lo..hi and gradient bins 0..gHi is occupied is then two lookups (occupiedIn).
std::vector<float> occupancyTable(const std::vector<std::uint8_t>& lut);
bool occupiedIn(const std::vector<float>& table, int lo, int hi, int gHi);

} // namespace steerseg::render
