#include "scan/dicom/codestream.hpp"

#include <gdcmImage.h>
#include <gdcmSequenceOfFragments.h>
#include <string>

namespace steerseg::scan {

namespace {

std::uint32_t be16(std::span<const std::uint8_t> b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) << 8 | b[at + 1];
}
std::uint32_t be32(std::span<const std::uint8_t> b, std::size_t at) {
    return be16(b, at) << 16 | be16(b, at + 2);
}

[[noreturn]] void mismatch(const std::filesystem::path& file, const std::string& codec,
                           const std::string& what) {
    throw ScanError(file, "the " + codec + " codestream does not match the DICOM header: " + what);
}

void checkSize(const std::filesystem::path& file, const std::string& codec, std::uint64_t width,
               std::uint64_t height, std::uint64_t components, std::uint64_t precision,
               const ExpectedFrame& e) {
    if (width != static_cast<std::uint64_t>(e.columns) ||
        height != static_cast<std::uint64_t>(e.rows)) {
        mismatch(file, codec,
                 "it is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", the header says " + std::to_string(e.columns) + "x" +
                     std::to_string(e.rows));
    }
    if (components != static_cast<std::uint64_t>(e.samples)) {
        mismatch(file, codec,
                 std::to_string(components) + " components, header says " +
                     std::to_string(e.samples));
    }
    if (precision == 0 || precision > static_cast<std::uint64_t>(e.bitsAllocated)) {
        mismatch(file, codec,
                 std::to_string(precision) + "-bit samples in " + std::to_string(e.bitsAllocated) +
                     " allocated bits");
    }
}

// SIZ marker segment at `at` (just after SOC).
void checkSiz(const std::filesystem::path& file, std::span<const std::uint8_t> b, std::size_t at,
              const ExpectedFrame& e) {
    const std::string codec = "JPEG 2000";
    if (b.size() < at + 40 || be16(b, at) != 0xff51) {
        mismatch(file, codec, "no SIZ marker after SOC");
    }
    const std::uint64_t xsiz = be32(b, at + 6), ysiz = be32(b, at + 10);
    const std::uint64_t xo = be32(b, at + 14), yo = be32(b, at + 18);
    const std::uint32_t csiz = be16(b, at + 38);
    if (xo >= xsiz || yo >= ysiz || csiz == 0 || b.size() < at + 40 + 3 * std::size_t{csiz}) {
        mismatch(file, codec, "its SIZ marker is malformed");
    }
    std::uint64_t precision = 0;
    for (std::uint32_t c = 0; c < csiz; ++c) {
        const std::size_t p = at + 40 + 3 * std::size_t{c};
        const std::uint64_t bits = (b[p] & 0x7fU) + 1U;
        if (c > 0 && bits != precision) {
            mismatch(file, codec, "components differ in precision");
        }
        precision = bits;
        if (b[p + 1] != 1 || b[p + 2] != 1) {
            mismatch(file, codec, "a component is subsampled");
        }
    }
    checkSize(file, codec, xsiz - xo, ysiz - yo, csiz, precision, e);
}

// JPEG and JPEG-LS: markers after SOI up to the first SOFn (or SOF55 for JPEG-LS).
bool checkJpeg(const std::filesystem::path& file, std::span<const std::uint8_t> b,
               const ExpectedFrame& e) {
    std::size_t at = 2;
    while (at + 4 <= b.size()) {
        if (b[at] != 0xff) {
            mismatch(file, "JPEG", "a marker is expected at byte " + std::to_string(at));
        }
        const std::uint8_t m = b[at + 1];
        if (m == 0xff) {
            ++at; // fill byte
            continue;
        }
        const std::uint32_t length = be16(b, at + 2);
        const bool sof =
            (m >= 0xc0 && m <= 0xcf && m != 0xc4 && m != 0xc8 && m != 0xcc) || m == 0xf7;
        if (sof) {
            if (length < 8 || at + 2 + length > b.size()) {
                mismatch(file, "JPEG", "its frame header is truncated");
            }
            const std::string codec = m == 0xf7 ? "JPEG-LS" : "JPEG";
            checkSize(file, codec, be16(b, at + 7), be16(b, at + 5), b[at + 9], b[at + 4], e);
            // JPEG and JPEG-LS samples are at most 16 bits, stored in 8 or 16 (PS3.5 8.2); with
            // 32 allocated, GDCM 3.0.21's JPEG-LS codec asserts and aborts (found by fuzz_dicom).
            if (e.bitsAllocated > 16) {
                mismatch(file, codec,
                         std::to_string(e.bitsAllocated) +
                             " allocated bits per sample, where JPEG stores 8 or 16");
            }
            return true;
        }
        if (m == 0xda || length < 2) {
            break; // scan data before any frame header
        }
        at += 2 + length;
    }
    mismatch(file, "JPEG", "no frame header (SOF) before the scan data");
}

bool jpegFamily(const gdcm::TransferSyntax& ts) {
    using T = gdcm::TransferSyntax;
    switch (static_cast<T::TSType>(ts)) {
    case T::JPEGBaselineProcess1:
    case T::JPEGExtendedProcess2_4:
    case T::JPEGExtendedProcess3_5:
    case T::JPEGSpectralSelectionProcess6_8:
    case T::JPEGFullProgressionProcess10_12:
    case T::JPEGLosslessProcess14:
    case T::JPEGLosslessProcess14_1:
    case T::JPEGLSLossless:
    case T::JPEGLSNearLossless:
    case T::JPEG2000Lossless:
    case T::JPEG2000:
    case T::JPEG2000Part2Lossless:
    case T::JPEG2000Part2:
        return true;
    default:
        return false;
    }
}

std::uint32_t le32(std::span<const std::uint8_t> b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
           static_cast<std::uint32_t>(b[at + 2]) << 16 |
           static_cast<std::uint32_t>(b[at + 3]) << 24;
}

// An RLE frame: a 64-byte header with the segment count (one per byte of each sample) and
// increasing segment offsets inside the fragment. GDCM 3.0.21's RLECodec trusts the count and
// reads out of bounds otherwise (found by fuzz_dicom).
void checkRleFrame(const std::filesystem::path& file, std::span<const std::uint8_t> b,
                   const ExpectedFrame& e) {
    const std::uint32_t wanted = static_cast<std::uint32_t>(e.samples * (e.bitsAllocated / 8));
    if (b.size() < 64) {
        mismatch(file, "RLE", "a frame is shorter than its 64-byte header");
    }
    const std::uint32_t segments = le32(b, 0);
    if (segments != wanted || segments > 15) {
        mismatch(file, "RLE",
                 std::to_string(segments) + " segments where " + std::to_string(wanted) +
                     " are expected");
    }
    std::uint32_t previous = 0;
    for (std::uint32_t s = 0; s < segments; ++s) {
        const std::uint32_t offset = le32(b, 4 + 4 * std::size_t{s});
        if ((s == 0 && offset != 64) || (s > 0 && offset <= previous) || offset >= b.size()) {
            mismatch(file, "RLE",
                     "segment " + std::to_string(s + 1) + " starts at byte " +
                         std::to_string(offset) + " of a " + std::to_string(b.size()) +
                         "-byte frame");
        }
        previous = offset;
    }
}

} // namespace

bool checkCodestream(const std::filesystem::path& file, std::span<const std::uint8_t> fragment,
                     const ExpectedFrame& expected) {
    const auto& b = fragment;
    if (b.size() >= 4 && b[0] == 0xff && b[1] == 0x4f) {
        checkSiz(file, b, 2, expected);
        return true;
    }
    if (b.size() >= 12 && be32(b, 4) == 0x6a502020) { // JP2 signature box "jP  "
        for (std::size_t at = 12; at + 8 <= b.size() && at < 4096; ++at) {
            if (be32(b, at) == 0x6a703263 && at + 6 <= b.size() && b[at + 4] == 0xff &&
                b[at + 5] == 0x4f) { // "jp2c" box then SOC
                checkSiz(file, b, at + 6, expected);
                return true;
            }
        }
        mismatch(file, "JPEG 2000", "no codestream inside the JP2 box");
    }
    if (b.size() >= 4 && b[0] == 0xff && b[1] == 0xd8) {
        return checkJpeg(file, b, expected);
    }
    return false;
}

void checkCompressedFrames(const std::filesystem::path& file, const gdcm::Image& image) {
    const gdcm::TransferSyntax ts = image.GetTransferSyntax();
    if (!ts.IsEncapsulated()) {
        return;
    }
    const gdcm::SequenceOfFragments* fragments = image.GetDataElement().GetSequenceOfFragments();
    if (fragments == nullptr) {
        throw ScanError(file, "the compressed pixel data has no fragments");
    }
    const gdcm::PixelFormat& pf = image.GetPixelFormat();
    const ExpectedFrame expected{
        static_cast<int>(image.GetDimension(1)), static_cast<int>(image.GetDimension(0)),
        static_cast<int>(pf.GetSamplesPerPixel()), static_cast<int>(pf.GetBitsAllocated())};
    const bool rle = ts == gdcm::TransferSyntax::RLELossless;
    const std::size_t frames = image.GetNumberOfDimensions() > 2 ? image.GetDimension(2) : 1U;
    if (rle && fragments->GetNumberOfFragments() != frames) {
        throw ScanError(file, "the RLE pixel data has " +
                                  std::to_string(fragments->GetNumberOfFragments()) +
                                  " fragments for " + std::to_string(frames) + " frames");
    }
    std::size_t recognised = 0;
    for (unsigned f = 0; f < fragments->GetNumberOfFragments(); ++f) {
        const gdcm::ByteValue* bv = fragments->GetFragment(f).GetByteValue();
        if (bv == nullptr || bv->GetPointer() == nullptr) {
            if (rle) {
                throw ScanError(file, "an RLE frame is empty");
            }
            continue;
        }
        const std::span<const std::uint8_t> bytes(
            reinterpret_cast<const std::uint8_t*>(bv->GetPointer()), bv->GetLength());
        if (rle) {
            checkRleFrame(file, bytes, expected);
        } else {
            recognised += checkCodestream(file, bytes, expected) ? 1U : 0U;
        }
    }
    if (jpegFamily(ts) && recognised == 0) {
        throw ScanError(file, "the compressed pixel data holds no JPEG codestream");
    }
}

} // namespace steerseg::scan
