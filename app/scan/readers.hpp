#pragma once

// One reader per format, each in its own file; scan_reader.cpp picks one.
#include "scan/scan_reader.hpp"

namespace steerseg::scan {

class SeekableSource;
struct DicomSource;

Volume readNifti(const std::filesystem::path& path, const ReadLimits& limits, std::string& format);
Volume readNrrd(const std::filesystem::path& path, const ReadLimits& limits);
Volume readMetaImage(const std::filesystem::path& path, const ReadLimits& limits);
Volume readMgz(const std::filesystem::path& path, const ReadLimits& limits);
// A folder of 2D images (sorted by name) or one multi-page TIFF, through OpenImageIO.
Volume readImageStack(const std::filesystem::path& path, const ReadLimits& limits);
// A folder holding a DICOM series, or one DICOM file (single- or multi-frame). Where `source` is
// given, it receives what DICOM SEG export needs of the series (io/dicom_source.hpp).
Volume readDicom(const std::filesystem::path& path, const ReadLimits& limits,
                 DicomSource* source = nullptr);

// The same readers over an open source (a file, or bytes in memory for fuzz targets). `path`
// names the scan in messages; detached data files (.nhdr, .mhd) are looked up beside it.
Volume readNiftiFrom(const std::filesystem::path& path, SeekableSource& file,
                     const ReadLimits& limits, std::string& format);
Volume readNrrdFrom(const std::filesystem::path& path, SeekableSource& file,
                    const ReadLimits& limits);
Volume readMetaImageFrom(const std::filesystem::path& path, SeekableSource& file,
                         const ReadLimits& limits);
Volume readMgzFrom(const std::filesystem::path& path, SeekableSource& file,
                   const ReadLimits& limits);

// True if the file starts like DICOM Part 10 ("DICM" at offset 128).
bool looksLikeDicom(const std::filesystem::path& path);

} // namespace steerseg::scan
