#pragma once

// Finds the one image series in a folder of DICOM files.
#include "scan/dicom/header.hpp"

#include <vector>

namespace steerseg::scan {

struct DicomFolderScan {
    std::vector<DicomHeader> images;   // files with pixel data, sorted by name
    std::size_t notDicom = 0;          // files that do not look like DICOM (skipped)
    std::vector<std::string> nonImage; // DICOM objects without an image ("RTSTRUCT", ...)
};

// Reads the header of every DICOM file directly in `folder` (not in subfolders). Files that are
// not DICOM are skipped; a DICOM file GDCM cannot parse is an error (a silently dropped slice
// would change the geometry).
DicomFolderScan scanDicomFolder(const std::filesystem::path& folder, const ReadLimits& limits);

// The images of the folder's single series (same SeriesInstanceUID, orientation and size; a
// multi-frame file is a series of its own). Throws ScanError if there is no image, or listing
// the series (UID, description, slice count) if there is more than one: we never pick one.
std::vector<DicomHeader> selectSeries(const std::filesystem::path& folder, DicomFolderScan scan);

// "RTSTRUCT (SOP class 1.2.840.10008.5.1.4.1.1.481.3)": what a non-image object is.
std::string describeNonImage(const DicomHeader& h);

} // namespace steerseg::scan
