#pragma once

// Index-to-world affines, the form most headers store geometry in, and their conversion to and
// from Geometry (spacing = column lengths, direction = unit columns).
#include "core/volume.hpp"

#include <filesystem>

namespace steerseg::scan {

// world = linear * index + offset (index in voxels, i fastest).
struct Affine {
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};
};

Affine affineOf(const Geometry& geometry);

// Splits `affine` into spacing and unit direction columns on a grid of `dims`, then checks the
// result with checkGeometry (ScanError naming `path` for zero/NaN spacing or a sheared grid).
Geometry geometryFromAffine(const std::filesystem::path& path, const Affine& affine,
                            const glm::ivec3& dims);

// RAS (NIfTI, FreeSurfer) <-> LPS (DICOM, ITK, this app): negate the first two world axes. The
// same function converts both ways.
Affine flipRasLps(const Affine& affine);

// True if the columns of `m` are orthogonal within `tolerance` after normalising (no shear).
bool hasOrthogonalColumns(const glm::dmat3& m, double tolerance = 1e-3);

} // namespace steerseg::scan
