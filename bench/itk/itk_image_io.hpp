#pragma once

// ITK-side image files for the ITK comparison benchmark. The benchmark never links steerseg's
// own readers, so that a disagreement between the two solvers cannot hide a shared I/O bug.

#include <cstdint>
#include <itkImage.h>
#include <string>

namespace steerseg::itkbench {

using FloatImage = itk::Image<float, 3>;
using MaskImage = itk::Image<std::uint8_t, 3>;

// Reads a scan as float, with the file's scaling applied (NIfTI scl_slope/scl_inter) and ITK's
// index order, which for NIfTI and NRRD is the file's storage order. Throws std::runtime_error
// "path: problem" for unreadable files and for grids too large to be a medical scan.
FloatImage::Pointer readFloatImage(const std::string& path);

// Reads a mask; any non-zero voxel counts as inside (stored as 1).
MaskImage::Pointer readMask(const std::string& path);

// Writes a mask (.nii.gz, .nii or .nrrd) with its own geometry. Throws std::runtime_error.
void writeMask(const std::string& path, const MaskImage* mask);

// Empty when the two grids match (dims exactly; spacing, origin and direction to within 1e-4
// relative), else a one-line description of the first difference.
std::string gridMismatch(const itk::ImageBase<3>* a, const itk::ImageBase<3>* b);

} // namespace steerseg::itkbench
