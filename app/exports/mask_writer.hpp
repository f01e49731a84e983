#pragma once

#include "core/volume.hpp"

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <span>
#include <string>

namespace steerseg::exports {

// Writes a binary mask (1 inside, 0 outside; one uint8 per voxel, i fastest) on `geometry`'s
// grid, so that it overlays the scan exactly in ITK-SNAP and 3D Slicer. The format follows the
// extension: .nii.gz, .nii or .nrrd (gzip). Writes to a temporary name and renames, so a crash
// never leaves a half-written mask under the final name. Throws files::WriteError.
void writeMask(const std::filesystem::path& path, const Geometry& geometry,
               std::span<const std::uint8_t> mask);

// A label map: each voxel's value as it is (0 outside, a structure's label value inside), in the
// formats and on the grid of writeMask. Throws files::WriteError.
void writeLabelMap(const std::filesystem::path& path, const Geometry& geometry,
                   std::span<const std::uint8_t> labels);

// Every mask writer's first check: a valid grid (checkGeometry) and one byte per voxel of it;
// files::WriteError naming `path` otherwise.
void checkMaskSize(const std::filesystem::path& path, const Geometry& geometry,
                   std::span<const std::uint8_t> mask);

// One segment of a 3D Slicer segmentation: what Slicer shows in its segment list.
struct SegmentInfo {
    std::string name = "Segment_1";
    std::string id;                        // empty: the name
    glm::dvec3 color{0.945, 0.839, 0.569}; // r g b within 0..1 (Slicer's first default)
    int label = 1;                         // 1..255, the voxels' value inside
    std::string tags = "Segmentation.Status:completed|";
};

// 3D Slicer's segmentation file (.seg.nrrd) of one segment (slicer_segmentation.hpp writes
// several): a gzip NRRD on `geometry`'s grid exactly as
// writeMask's .nrrd (LPS space, space directions, space origin), the voxels the segment's label
// inside and 0 outside, and the Segment0_* and Segmentation_* keys Slicer reads (name, colour,
// label value, layer, extent, tags; binary labelmap master representation). Throws
// files::WriteError on a bad segment (label outside 1..255, empty name, a '|' or line break in a
// name or id) as for writeMask.
void writeSegmentation(const std::filesystem::path& path, const Geometry& geometry,
                       std::span<const std::uint8_t> mask, const SegmentInfo& segment = {});

} // namespace steerseg::exports
