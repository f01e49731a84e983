#pragma once

// The names and colours of a label map's values, beside it, as an ITK-SNAP label description
// file (ITK-SNAP: Segmentation > Import Label Descriptions; also read by 3D Slicer's
// ITK-SNAP colour table reader and by nnU-Net tooling).
#include "exports/mask_writer.hpp"

#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace steerseg::exports {

// `X.nii.gz`, `X.nii`, `X.nrrd` (any case) -> `X.label.txt`; any other name gets `.label.txt`
// appended.
std::filesystem::path labelDescriptionPathFor(const std::filesystem::path& labelMapPath);

// The header comment ITK-SNAP writes, then "Clear Label" for 0 and one row per segment (its
// label value, colour 0..255, opaque, visible, meshed, the name in double quotes; a '"' in a name
// becomes '\''), atomically. Throws files::WriteError.
void writeLabelDescription(const std::filesystem::path& path, std::span<const SegmentInfo> labels);

struct DescribedLabel {
    int value = 0;
    std::string name;
};

// The labels a description file names, 0 ("Clear Label") left out, in the file's order. Reads
// what ITK-SNAP and writeLabelDescription write: '#' comments, then rows of seven numbers and a
// quoted name. Throws std::runtime_error naming the file and line of a row it cannot read, a
// value outside 0..65535 or given twice.
std::vector<DescribedLabel> readLabelDescription(const std::filesystem::path& path);

} // namespace steerseg::exports
