#pragma once

// The one rule by which a mask file's voxel is inside or outside, for every path that reads a
// mask (export, a session started from a mask, the Dice of a mask against a reference): inside
// is any non-zero real value, so a label of -1 or a probability of 0.4 counts as much as 1. A NaN
// says neither, and guessing would export a different segmentation than the file holds, so a
// mask holding one is refused.
#include "core/volume.hpp"

#include <cstdint>
#include <vector>

namespace steerseg {

// Throws std::invalid_argument with one line for NaN.
bool insideValue(double value);

// 1 where the mask's real value is inside, else 0. Throws std::invalid_argument with one line
// naming the first NaN voxel.
std::vector<std::uint8_t> maskInside(const Volume& mask);

} // namespace steerseg
