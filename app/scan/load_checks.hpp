#pragma once

// Checks every reader makes, so hostile files fail the same way whatever their format.
#include "scan/scan_reader.hpp"

#include <cstdint>

namespace steerseg::scan {

class ByteSource;

// Refuses non-positive or absurd dimensions and voxel counts past `limits`, before anything is
// allocated. `what` describes the source ("header", "DICOM series").
void checkDims(const std::filesystem::path& path, const glm::ivec3& dims, const ReadLimits& limits);

// Refuses zero, negative, NaN or infinite spacing, and a direction matrix that is not a rotation
// (columns not unit length or not orthogonal within `tolerance`).
void checkGeometry(const std::filesystem::path& path, const Geometry& geometry,
                   double tolerance = 1e-3);

// Refuses float voxels that are NaN or infinite, naming how many and the first one's index.
void checkFinite(const std::filesystem::path& path, const Volume& volume);

// Refuses reading `needed` bytes where only `available` remain in the file.
void checkAvailable(const std::filesystem::path& path, std::uint64_t needed,
                    std::uint64_t available, const char* what);

// Refuses a rescale that does not take the volume's stored range to finite float32 values
// (rescaleProblem), naming the file and the header `fields` it came from ("scl_slope/scl_inter").
void checkRescale(const std::filesystem::path& path, const Rescale& rescale, double storedMin,
                  double storedMax, const std::string& fields);
void checkRescale(const std::filesystem::path& path, const Volume& volume,
                  const std::string& fields);

// Refuses `bytes` of declared voxel data (`what`, as below) past limits.maxDataBytes.
void checkDataLimit(const std::filesystem::path& path, std::uint64_t bytes,
                    const ReadLimits& limits, const std::string& what);

// Refuses `bytes` of declared voxel data (`what`: "header says 512x512x300 int16 (150 MiB)")
// past limits.maxDataBytes, or, for a compressed source, more than its compressed bytes can
// expand to at limits.maxCompressionRatio. Called before the data is read, so a decompression
// bomb or a lying header allocates nothing. (Uncompressed shortfalls are readExactly's.)
void checkDataFits(const std::filesystem::path& path, std::uint64_t bytes, const ByteSource& source,
                   const ReadLimits& limits, const std::string& what);

} // namespace steerseg::scan
