#pragma once

#include "core/volume.hpp"
#include "files/file_error.hpp"
#include "scan/dicom_source.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace steerseg::scan {

// A scan that cannot be read. what() is one line naming the file and the problem:
// "scan.nii.gz: header says 512x512x300 int16 (150 MiB) but the data ends after 12 MiB".
class ScanError : public files::FileError {
  public:
    using files::FileError::FileError;
};

// Caps that keep a hostile header from making us allocate or loop beyond reason. A loader
// never allocates more voxel memory than the file can back (compressed data grows as it is
// actually decoded), and refuses dimensions past these caps up front.
struct ReadLimits {
    std::size_t maxVoxels = std::size_t{1} << 31; // 2 Gi voxels (an 1290^3 scan)
    int maxDimension = 65536;                     // per axis
    // Voxel data a scan may declare, as stored in the file before conversion: 4 GiB holds a
    // 1024^3 float32 or a 1290^3 int16 scan.
    std::uint64_t maxDataBytes = std::uint64_t{4} << 30;
    // How far compressed data may expand. Deflate (gzip, zlib, DICOM deflate) cannot exceed
    // 1032:1 (a 258-byte match in 2 bits), so a header declaring more than the compressed bytes
    // times this is refused before anything is decoded; a genuine file never is.
    double maxCompressionRatio = 1032.0;
};

struct LoadedScan {
    Volume volume;
    std::string
        format; // "nifti", "nifti2", "nrrd", "metaimage", "mgz", "dicom", "image-stack", "builtin"
    // The source series of a scan read from DICOM (for DICOM SEG export); null otherwise.
    std::shared_ptr<const DicomSource> dicom = nullptr;
};

// The pseudo-path naming the built-in sample phantom.
inline constexpr const char* kBuiltinSample = "builtin:sample";

// Reads any supported scan: a DICOM series folder or file, NIfTI-1/2, NRRD, MetaImage, MGZ, a
// folder of 2D images or a multi-page TIFF, or kBuiltinSample. Chooses the reader from the
// folder's contents, the extension and the magic bytes. Throws ScanError.
LoadedScan readScan(const std::filesystem::path& path, const ReadLimits& limits = {});

} // namespace steerseg::scan
