#pragma once

// The DICOM SEG's frame layout (which segment on which slice, and the 1-bit Pixel Data) apart
// from dicom_seg_writer.cpp: the packing replaces what DCMTK writes, so it is kept free of DCMTK
// and can be checked bit by bit without building a segmentation.
#include "core/volume.hpp"
#include "exports/dicom_seg_writer.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace steerseg::exports {

// One frame: a segment (its index in the list) on a slice.
struct Frame {
    std::size_t segment = 0;
    int k = 0;
};

// The slices that hold segmented voxels of one segment, ascending.
std::vector<int> segmentedSlices(const Geometry& g, std::span<const std::uint8_t> mask);

// 1-bit frames packed back to back, least significant bit first, with no padding between
// frames (PS3.5 8.1.1), the whole padded to an even length. DCMTK 3.6.7's dcmseg packs frames
// whose pixel count is not a multiple of 8 wrongly (the independent reader in the tests caught
// it), so the Pixel Data it wrote is replaced by this.
std::vector<std::uint8_t> packFrames(const Geometry& g, std::span<const DicomSegment> segments,
                                     const std::vector<Frame>& frames);

} // namespace steerseg::exports
