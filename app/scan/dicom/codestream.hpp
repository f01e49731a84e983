#pragma once

// Checks compressed frames against the DICOM header before GDCM decodes them. GDCM 3.0.21
// sizes its output from the header but lets the codec write what the codestream declares: a
// JPEG 2000 frame whose SIZ marker claims more rows than the header (found by fuzz_dicom) makes
// JPEG2000Codec write past its buffer. Refusing mismatched codestreams first avoids that.
#include "scan/scan_reader.hpp"

#include <cstdint>
#include <span>

namespace gdcm {
class Image;
} // namespace gdcm

namespace steerseg::scan {

struct ExpectedFrame {
    int rows = 0;
    int columns = 0;
    int samples = 1;
    int bitsAllocated = 16;
};

// Checks one fragment of encapsulated pixel data. A fragment that starts a JPEG 2000 (SOC SIZ,
// raw or inside a JP2 box), JPEG or JPEG-LS (SOI ... SOFn) codestream must declare the expected
// size, component count and no more bits than allocated; other fragments are not checked.
// Returns true if the fragment started a recognised codestream. Throws ScanError on mismatch.
bool checkCodestream(const std::filesystem::path& file, std::span<const std::uint8_t> fragment,
                     const ExpectedFrame& expected);

// Checks every fragment of an image's encapsulated pixel data with checkCodestream; a JPEG,
// JPEG-LS or JPEG 2000 transfer syntax must hold at least one recognised codestream. RLE frames
// (one fragment each) must have a consistent segment header.
void checkCompressedFrames(const std::filesystem::path& file, const gdcm::Image& image);

} // namespace steerseg::scan
