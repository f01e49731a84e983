#pragma once

#include "scan/raw_data.hpp"
#include "scan/scan_reader.hpp"

#include <string_view>

namespace steerseg::scan {

// Parses a MetaImage header (ITK MetaIO "Key = Value" lines ending with ElementDataFile) held in
// `text`. ElementDataFile = LOCAL: the data follows the header in the same file (.mha); a file
// name: detached data beside the header (.mhd). World coordinates are LPS as ITK writes them.
// Throws ScanError naming `path`.
RawDataSpec parseMetaImageHeader(const std::filesystem::path& path, std::string_view text,
                                 const ReadLimits& limits);

} // namespace steerseg::scan
