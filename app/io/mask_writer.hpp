#pragma once

#include "core/volume.hpp"

#include <cstdint>
#include <filesystem>
#include <span>

namespace steerseg::io {

// Writes a binary mask (1 inside, 0 outside; one uint8 per voxel, i fastest) on `geometry`'s
// grid, so that it overlays the scan exactly in ITK-SNAP and 3D Slicer. The format follows the
// extension: .nii.gz, .nii or .nrrd (gzip). Writes to a temporary name and renames, so a crash
// never leaves a half-written mask under the final name. Throws io::WriteError.
void writeMask(const std::filesystem::path& path, const Geometry& geometry,
               std::span<const std::uint8_t> mask);

} // namespace steerseg::io
