#pragma once

// Enhanced multi-frame objects (Enhanced CT/MR/PET, ...) give each frame's position, orientation,
// pixel spacing and rescale in functional group sequences instead of top-level attributes.
#include "scan/dicom/header.hpp"

namespace steerseg::scan {

// Fills h.planes (one per frame), h.orientation, h.pixelSpacing and slice spacing from the
// Shared (5200,9229) and Per-Frame (5200,9230) Functional Groups where present; sets
// h.framesFromGroups when every frame has its own position. Throws ScanError on malformed values.
void readFunctionalGroups(const std::filesystem::path& path, const gdcm::DataSet& ds,
                          DicomHeader& h);

} // namespace steerseg::scan
