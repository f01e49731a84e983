#pragma once

// The NRRD header every NRRD export shares (a mask, a label map, a 3D Slicer segmentation): the
// scan's grid in LPS, so that the voxels overlay the scan in ITK-SNAP and 3D Slicer.
#include "core/volume.hpp"

#include <string>

namespace steerseg::exports {

// uint8 voxels, gzip, on `g`'s grid. `comment` says what the voxels hold; `keyValues`
// ("key:=value" lines) follow the fields. `layers` > 0 adds a first axis of that many layers
// (kind "list", no space direction): 3D Slicer's layered segmentation, each voxel's layers
// stored together.
std::string nrrdHeader(const Geometry& g, const std::string& comment, const std::string& keyValues,
                       int layers = 0);

} // namespace steerseg::exports
