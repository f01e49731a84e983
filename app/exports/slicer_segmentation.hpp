#pragma once

// 3D Slicer's segmentation file (.seg.nrrd) with any number of segments, as Slicer's
// vtkMRMLSegmentationStorageNode writes and reads it.
#include "core/volume.hpp"
#include "exports/mask_writer.hpp"

#include <cstdint>
#include <filesystem>
#include <span>

namespace steerseg::exports {

struct SlicerSegment {
    SegmentInfo info{};
    std::span<const std::uint8_t> mask{}; // non-zero inside, i fastest, on the geometry's grid
};

// Writes `segments` (Segment0_* for the first, in this order) on `geometry`'s grid as a gzip
// NRRD with writeMask's LPS fields. Where no two segments share a voxel, one layer: a 3D label
// map holding each segment's label value (Segment<k>_Layer 0). Where any two do, one layer per
// segment: a 4D NRRD whose first axis (kind "list", no space direction) holds the layers, each
// with its segment's label value inside (Segment<k>_Layer k). Throws files::WriteError with one
// line: no segment, a mask off the grid, a label outside 1..255 or one used twice, an empty name,
// a colour outside 0..1, a '|' or line break in a name or id, an id used twice.
void writeSegmentation(const std::filesystem::path& path, const Geometry& geometry,
                       std::span<const SlicerSegment> segments);

} // namespace steerseg::exports
