#pragma once

// A structural check of a DICOM file before GDCM parses it. Debian's GDCM is built with
// assertions on, and some malformed inputs (a file cut inside its meta header, element lengths
// past the end, broken sequence nesting) end in assert() and abort() inside GDCM instead of an
// error return. Walking the element structure ourselves first turns those into ScanError.
#include "scan/scan_reader.hpp"

#include <cstdint>

namespace steerseg::scan {

// Nesting deeper than this is refused (GDCM recurses once per level).
inline constexpr int kMaxDicomNesting = 32;

// Walks the preamble, the meta header and every data element (sequences and items recursively,
// encapsulated pixel data fragment by fragment), checking that each length fits its container
// and each explicit VR is valid. A deflated data set is checked up to its meta header only.
// Throws ScanError(path, "...: element (gggg,eeee) at byte N ..."). Returns where the data set
// ends: the file size, or where trailing zero padding starts.
std::uint64_t checkDicomStructure(const std::filesystem::path& path);

} // namespace steerseg::scan
