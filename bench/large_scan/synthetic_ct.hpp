#pragma once

// A synthetic CT series of any size, written as DICOM files (one per slice), for the
// large-scan benchmark: no big file lives in the repository.
#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>

namespace steerseg::bench {

struct SyntheticCt {
    glm::ivec3 dims{512, 512, 1000};
    glm::dvec3 spacing{0.7, 0.7, 1.0}; // mm
    // A lesion ball of 120 HU in 40 HU soft tissue of an elliptic body in air, noise +-15 HU.
    glm::dvec3 lesionCentre{0.0}; // voxels; set by write()
    double lesionRadius = 0.0;    // voxels in i and j
    std::size_t lesionVoxels = 0; // voxels inside the lesion (the segmentation's truth)
};

// Writes `ct.dims.z` files slice0000.dcm ... into `dir` (int16 stored, rescale -1024), one
// series, ascending positions along z. Fills in the lesion's place and true size.
void writeSyntheticCt(SyntheticCt& ct, const std::filesystem::path& dir);

} // namespace steerseg::bench
