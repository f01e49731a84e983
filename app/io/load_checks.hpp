#pragma once

// Checks every reader makes, so hostile files fail the same way whatever their format.
#include "io/scan_reader.hpp"

#include <cstdint>

namespace steerseg::io {

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

// "512x512x300".
std::string dimsText(const glm::ivec3& dims);

} // namespace steerseg::io
