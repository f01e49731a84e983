#pragma once

#include "itk_image_io.hpp"

#include <span>
#include <string>

namespace steerseg::itkbench {

// A seed sphere in voxel indices: centre (i, j, k) in the file's storage order, radius r in
// voxels, like steerseg's --seed i,j,k,r.
struct Seed {
    double i = 0.0;
    double j = 0.0;
    double k = 0.0;
    double r = 0.0;
};

// "i,j,k,r" -> Seed; throws cli::UsageError naming --seed on malformed text or r <= 0.
Seed parseSeed(const std::string& text);

// What a seed's radius measures. Millimetres: the product's spheres (model::Sphere), r voxels
// along the grid's finest axis and round in mm, so that `steerseg segment` and ITK start from
// the same surface on an anisotropic scan. Voxels: a ball in voxel steps whatever the spacing,
// as ITK's own examples draw it (segment_bench --voxel-spheres 1 seeds the same ball).
enum class SeedSpheres { Millimetres, Voxels };

// The initial level set on `grid`'s grid: signed distance, in voxel steps, to the union of the
// seed spheres, negative inside (min over seeds; round in mm, the product's
// model::sphereDistance). Its zero set is exact; inside an overlap of spheres the magnitude is
// not the true distance, which the sparse-field solver never reads because it rebuilds its
// layers from the zero crossing. Throws std::runtime_error when a seed centre lies outside the
// grid.
FloatImage::Pointer seedLevelSet(const itk::ImageBase<3>* grid, std::span<const Seed> seeds,
                                 SeedSpheres spheres = SeedSpheres::Millimetres);

} // namespace steerseg::itkbench
