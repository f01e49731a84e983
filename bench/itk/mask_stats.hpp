#pragma once

#include "itk_image_io.hpp"
#include "seed_level_set.hpp"

namespace steerseg::itkbench {

// What the benchmark derives from an expert mask to set up a segmentation the way an operator
// would probe it: T and eps from the intensities inside, a seed well inside.
struct MaskStats {
    long long voxels = 0;
    double mean = 0.0;                    // of the scan's intensities inside the mask
    double std = 0.0;                     // population standard deviation, same voxels
    double centroid[3] = {0.0, 0.0, 0.0}; // voxel indices
    bool centroidInside = false;          // the nearest voxel to the centroid is in the mask
    long long deepest[3] = {0, 0, 0};     // the mask voxel farthest from the mask's border
    double depth = 0.0;                   // that distance, in voxels (unit spacing)
    Seed seed;                            // at `deepest`, radius clamp(depth / 2, 1, 3)
    // An operator's probe: the voxels within depth / 2 of `deepest` (all inside the mask), as
    // the paper sets T and eps from the mean and std of a probed region. The whole mask's std
    // is inflated by partial-volume voxels on its border.
    long long probeVoxels = 0;
    double probeMean = 0.0;
    double probeStd = 0.0;
};

// Throws std::runtime_error when the grids differ or the mask is empty.
MaskStats maskStats(const FloatImage* scan, const MaskImage* mask);

} // namespace steerseg::itkbench
