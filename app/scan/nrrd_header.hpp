#pragma once

#include "scan/raw_data.hpp"
#include "scan/scan_reader.hpp"

#include <string_view>

namespace steerseg::scan {

// Parses a NRRD header (NRRD0001-0005) held in `text`: the start of the file, or all of it where
// `wholeFile`. Attached data starts after the blank line ending the header (spec.headerBytes);
// a detached header (.nhdr) names its data file. World coordinates come out in LPS. Throws
// ScanError naming `path` for anything it cannot honour.
RawDataSpec parseNrrdHeader(const std::filesystem::path& path, std::string_view text,
                            bool wholeFile, const ReadLimits& limits);

} // namespace steerseg::scan
