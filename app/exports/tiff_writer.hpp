#pragma once

// A mask as a multi-page TIFF, for tools that read image stacks (ImageJ/Fiji, ITK-SNAP).
#include "core/volume.hpp"

#include <cstdint>
#include <filesystem>
#include <span>

namespace steerseg::exports {

// One page per slice k (page 0 = k 0), each page dims.x wide and dims.y tall with row j = 0 at
// the top, uint8: 255 inside, 0 outside (ImageJ's convention for a binary image, visible in any
// viewer), LZW-compressed. The in-plane spacing is in the resolution tags (pixels per
// centimetre, ResolutionUnit = cm); the slice spacing, which TIFF has no tag for, is in an
// ImageJ-style ImageDescription ("spacing=" in cm). A TIFF cannot hold the grid's position or
// orientation in the patient: the stack is in voxel order only. Written through OpenImageIO
// into an anonymous memory file, then to `path` by writeFileAtomically. Throws files::WriteError.
void writeTiffStack(const std::filesystem::path& path, const Geometry& geometry,
                    std::span<const std::uint8_t> mask);

// The caveat a caller shows with a TIFF export.
inline constexpr const char* kTiffGeometryNote =
    "TIFF holds no patient position or orientation: the stack is in voxel order, with the "
    "spacing only";

} // namespace steerseg::exports
