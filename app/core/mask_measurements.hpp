#pragma once

// Per-structure measurements of a binary mask on a scan's grid (docs/measurements.md): volume,
// surface area, the RECIST 1.1 diameters on the axial slices, the longest 3D diameter and the
// scan's values inside. Distances run between voxel centres in LPS millimetres (through the
// grid's spacing and direction), so a structure n voxels across measures (n - 1) spacings, not
// n: the voxel-centre convention of the exported mesh's vertices and the view's calipers.
#include "core/volume.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace steerseg {

// A measured segment with its two ends, for a view to draw.
struct MeasuredLine {
    double lengthMm = 0.0;
    std::array<glm::dvec3, 2> index{}; // the ends in voxel index coordinates (centres are whole)
    std::array<glm::dvec3, 2> world{}; // the same ends in LPS millimetres
};

// RECIST 1.1's pair on the axial slices.
struct AxialDiameters {
    int sliceAxis = 2; // the index axis axial slices step along (axialSliceAxis)
    int slice = 0;     // the slice (an index along sliceAxis) both lines lie on
    // The longest distance between two inside voxel centres of one axial slice, over all of
    // them (the lowest slice among equals); its ends are voxel centres.
    MeasuredLine longest;
    // The longest chord at right angles to `longest` across the same slice's inside voxel
    // centres' convex hull; its ends lie on the hull's edges, between voxel centres.
    MeasuredLine perpendicular;
};

// The scan's real values (HU on CT) over the inside voxels; sd over all of them (population).
struct MaskIntensity {
    double mean = 0.0;
    double sd = 0.0;
    double min = 0.0;
    double max = 0.0;
};

struct MaskMeasurements {
    std::uint64_t voxels = 0; // inside voxels
    double volumeMl = 0.0;    // voxels x the voxel's volume, exactly
    // The area of the mesh the STL and PLY exports write of this mask (extractSurface over
    // maskToField), so it is the area an operator measures on the exported file.
    double surfaceAreaMm2 = 0.0;
    AxialDiameters axial;
    MeasuredLine longest3d; // the longest distance between two inside voxel centres
    MaskIntensity intensity;
};

// The index axis the axial view steps along: the one whose direction is nearest the patient's
// superior-inferior axis, the first of equals, as render::sliceAxisFor(g, Axial) picks it, so a
// sagittal-acquired or oblique scan is measured on the slices the axial view shows.
int axialSliceAxis(const Geometry& geometry);

// `mask` is 0/1 (non-zero inside), one value per voxel of `scan`, i fastest. Throws
// std::invalid_argument when its size is not the scan's voxel count or no voxel is inside.
MaskMeasurements measureMask(const Volume& scan, std::span<const std::uint8_t> mask);

} // namespace steerseg
