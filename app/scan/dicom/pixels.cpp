#include "scan/dicom/pixels.hpp"

#include "scan/dicom/codestream.hpp"
#include "scan/dicom/isolated_decode.hpp"
#include "scan/load_checks.hpp"

#include <algorithm>
#include <cstring>
#include <gdcmImage.h>
#include <gdcmReader.h>
#include <limits>
#include <new>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace steerseg::scan {

namespace {

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

// Stored value -> value to keep: drops bits outside [HighBit-BitsStored+1, HighBit] of raw data
// (old files keep overlays there), sign-extends signed values, inverts MONOCHROME1.
struct StoredTransform {
    bool mask = false;
    unsigned shift = 0;
    unsigned bits = 0;
    bool isSigned = false;
    bool invert = false;
    std::int64_t invertBase = 0; // inverted = invertBase - value

    [[nodiscard]] std::int64_t apply(std::int64_t v) const {
        if (mask) {
            auto u = static_cast<std::uint64_t>(v) >> shift;
            u &= (std::uint64_t{1} << bits) - 1;
            v = static_cast<std::int64_t>(u);
            if (isSigned && (u >> (bits - 1)) != 0) {
                v -= std::int64_t{1} << bits;
            }
        }
        return invert ? invertBase - v : v;
    }
};

template <typename Dst> void storeInteger(std::int64_t v, Dst* dst) {
    if (v < std::numeric_limits<Dst>::min() || v > std::numeric_limits<Dst>::max()) {
        throw PixelPlanMismatch{};
    }
    *dst = static_cast<Dst>(v);
}

// Writes `count` values as `dstType`; real units (rescale applied) only into float32.
template <typename Src>
void convertFrame(const Src* src, std::size_t count, const StoredTransform& t, VoxelType dstType,
                  bool realUnits, const Rescale& rescale, std::byte* dstBytes) {
    if constexpr (std::is_floating_point_v<Src>) {
        if (dstType != VoxelType::Float32) {
            throw PixelPlanMismatch{};
        }
        auto* dst = reinterpret_cast<float*>(dstBytes);
        for (std::size_t n = 0; n < count; ++n) {
            const double v = t.invert ? -static_cast<double>(src[n]) : static_cast<double>(src[n]);
            dst[n] = static_cast<float>(rescale.apply(v));
        }
    } else {
        switch (dstType) {
        case VoxelType::Float32: {
            const Rescale r = realUnits ? rescale : Rescale{};
            auto* dst = reinterpret_cast<float*>(dstBytes);
            for (std::size_t n = 0; n < count; ++n) {
                dst[n] = static_cast<float>(
                    r.apply(static_cast<double>(t.apply(static_cast<std::int64_t>(src[n])))));
            }
            break;
        }
        case VoxelType::UInt8: {
            auto* dst = reinterpret_cast<std::uint8_t*>(dstBytes);
            for (std::size_t n = 0; n < count; ++n) {
                storeInteger(t.apply(static_cast<std::int64_t>(src[n])), dst + n);
            }
            break;
        }
        case VoxelType::Int16: {
            auto* dst = reinterpret_cast<std::int16_t*>(dstBytes);
            for (std::size_t n = 0; n < count; ++n) {
                storeInteger(t.apply(static_cast<std::int64_t>(src[n])), dst + n);
            }
            break;
        }
        case VoxelType::UInt16: {
            auto* dst = reinterpret_cast<std::uint16_t*>(dstBytes);
            for (std::size_t n = 0; n < count; ++n) {
                storeInteger(t.apply(static_cast<std::int64_t>(src[n])), dst + n);
            }
            break;
        }
        }
    }
}

// One frame's stored range as its rescale sees it (after masking and MONOCHROME1 inversion).
template <typename Src>
std::pair<double, double> storedRange(const Src* src, std::size_t count, const StoredTransform& t) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (std::size_t n = 0; n < count; ++n) {
        double v = 0.0;
        if constexpr (std::is_floating_point_v<Src>) {
            v = t.invert ? -static_cast<double>(src[n]) : static_cast<double>(src[n]);
        } else {
            v = static_cast<double>(t.apply(static_cast<std::int64_t>(src[n])));
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    return {lo, hi};
}

} // namespace

struct DicomPixels::Decoded {
    std::filesystem::path file;
    std::unique_ptr<std::istringstream> stream; // the data set without its padding
    gdcm::Reader reader;
    gdcm::Image image;
    std::vector<char> buffer;
    gdcm::PixelFormat format;
    bool monochrome1 = false;
    bool raw = false;
    std::size_t frameVoxels = 0;
    std::size_t frames = 0;
};

PixelPlan planPixels(std::span<const DicomHeader> files) {
    PixelPlan plan;
    bool first = true;
    bool sameType = true;
    bool sameRescale = true;
    VoxelType type = VoxelType::Float32;
    for (const DicomHeader& h : files) {
        VoxelType t = VoxelType::Float32;
        if (h.bitsAllocated == 8) {
            t = h.isSigned ? VoxelType::Int16 : VoxelType::UInt8;
        } else if (h.bitsAllocated == 16) {
            t = h.isSigned ? VoxelType::Int16 : VoxelType::UInt16;
        }
        for (const DicomFramePlane& p : h.planes) {
            if (first) {
                plan.shared = p.rescale;
                type = t;
                first = false;
            }
            sameRescale = sameRescale && p.rescale.slope == plan.shared.slope &&
                          p.rescale.intercept == plan.shared.intercept;
        }
        sameType = sameType && t == type;
    }
    if (sameType && sameRescale && type != VoxelType::Float32) {
        plan.type = type;
        plan.realUnits = false;
    } else {
        plan.type = VoxelType::Float32;
        plan.realUnits = true;
        plan.shared = Rescale{};
    }
    return plan;
}

DicomPixels::DicomPixels(const DicomHeader& header) : d_(std::make_unique<Decoded>()) {
    const auto& file = header.file;
    d_->file = file;
    try {
        openForGdcm(d_->reader, file, header.dataSetEnd, header.fileSize, d_->stream);
        if (!d_->reader.Read()) {
            throw ScanError(file, "GDCM cannot read the file (damaged or truncated)");
        }
        const gdcm::DataSet& ds = d_->reader.GetFile().GetDataSet();
        const gdcm::TransferSyntax ts = d_->reader.GetFile().GetHeader().GetDataSetTransferSyntax();
        const char* syntax = ts.GetString();
        const std::string encoding = syntax != nullptr ? syntax : "unknown transfer syntax";
        if (!ds.FindDataElement(kPixelData) || ds.GetDataElement(kPixelData).IsEmpty()) {
            throw ScanError(file, "the image has no pixel data (7fe0,0010)");
        }
        std::string photometric = header.photometric.empty() ? "MONOCHROME2" : header.photometric;
        if (header.samplesPerPixel != 1 ||
            (photometric != "MONOCHROME1" && photometric != "MONOCHROME2")) {
            throw ScanError(file, "colour image (" + photometric + ", " +
                                      std::to_string(header.samplesPerPixel) +
                                      " samples per pixel): only greyscale scans can be segmented");
        }
        // GDCM asserts (aborts the process) on a high bit other than bits stored - 1, as DICOM
        // now requires; older files that kept their bits higher are refused, not decoded.
        const int allocated = header.bitsAllocated;
        if ((allocated != 8 && allocated != 16 && allocated != 32) || header.bitsStored < 1 ||
            header.bitsStored > allocated || header.highBit >= allocated ||
            header.highBit + 1 != header.bitsStored) {
            throw ScanError(file, "unsupported pixel format: " + std::to_string(allocated) +
                                      " bits allocated, " + std::to_string(header.bitsStored) +
                                      " stored, high bit " + std::to_string(header.highBit));
        }
        // The image is described from our own header reading: gdcm::ImageReader would derive
        // geometry through gdcm::ImageHelper, which asserts (aborts) on malformed attributes.
        gdcm::Image& image = d_->image;
        image.SetNumberOfDimensions(header.frames > 1 ? 3U : 2U);
        image.SetDimension(0, static_cast<unsigned>(header.columns));
        image.SetDimension(1, static_cast<unsigned>(header.rows));
        if (header.frames > 1) {
            image.SetDimension(2, static_cast<unsigned>(header.frames));
        }
        image.SetPixelFormat(gdcm::PixelFormat(1, static_cast<unsigned short>(allocated),
                                               static_cast<unsigned short>(header.bitsStored),
                                               static_cast<unsigned short>(header.highBit),
                                               header.isSigned ? 1 : 0));
        image.SetPhotometricInterpretation(
            gdcm::PhotometricInterpretation::GetPIType(photometric.c_str()));
        image.SetTransferSyntax(ts);
        image.SetDataElement(ds.GetDataElement(kPixelData));
        // No SetNeedByteSwap: gdcm::Reader already byte-swaps big-endian OW pixel data.
        const std::size_t frames = static_cast<std::size_t>(header.frames);
        const unsigned dims[2] = {image.GetDimension(0), image.GetDimension(1)};
        const gdcm::PhotometricInterpretation pi = image.GetPhotometricInterpretation();
        d_->format = image.GetPixelFormat();
        d_->monochrome1 = pi == gdcm::PhotometricInterpretation::MONOCHROME1;
        switch (d_->format.GetScalarType()) {
        case gdcm::PixelFormat::UINT8:
        case gdcm::PixelFormat::INT8:
        case gdcm::PixelFormat::UINT16:
        case gdcm::PixelFormat::INT16:
        case gdcm::PixelFormat::UINT32:
        case gdcm::PixelFormat::INT32:
        case gdcm::PixelFormat::FLOAT32:
        case gdcm::PixelFormat::FLOAT64:
            break;
        default:
            throw ScanError(file, std::string("unsupported pixel format ") +
                                      d_->format.GetScalarTypeAsString() + " (" +
                                      std::to_string(d_->format.GetBitsAllocated()) +
                                      " bits allocated)");
        }
        d_->frameVoxels = static_cast<std::size_t>(dims[0]) * dims[1];
        d_->frames = frames;
        const std::size_t expected = d_->frameVoxels * frames * d_->format.GetPixelSize();
        if (image.GetBufferLength() != expected) {
            throw ScanError(file, "GDCM reports " + std::to_string(image.GetBufferLength()) +
                                      " bytes of pixel data where " + std::to_string(expected) +
                                      " were expected");
        }
        d_->raw = !image.GetTransferSyntax().IsEncapsulated();
        if (header.rawPixelData) {
            const gdcm::ByteValue* bv = image.GetDataElement().GetByteValue();
            checkAvailable(file, expected,
                           bv != nullptr ? static_cast<std::uint64_t>(bv->GetLength()) : 0U,
                           "pixel data");
        }
        checkCompressedFrames(file, image);
        d_->buffer.resize(expected);
        // Compressed frames go through GDCM's codecs, which can abort on malformed data: decode
        // them in a child process. Uncompressed data is a copy.
        const bool decoded =
            d_->raw ? image.GetBuffer(d_->buffer.data())
                    : decodeIsolated(file, std::span<char>(d_->buffer.data(), d_->buffer.size()),
                                     [&image](char* out) { return image.GetBuffer(out); });
        if (!decoded) {
            throw ScanError(file, "cannot decode the pixel data (" + encoding + ")");
        }
    } catch (const ScanError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw ScanError(file, "out of memory while decoding the pixel data");
    } catch (const std::exception& e) {
        throw ScanError(file, std::string("GDCM failed: ") + e.what());
    }
}

DicomPixels::~DicomPixels() = default;

void DicomPixels::copyFrames(std::span<const std::size_t> sliceOfFrame,
                             std::span<const DicomFramePlane> planes, const PixelPlan& plan,
                             Volume& out) const {
    const glm::ivec3 dims = out.dims();
    if (sliceOfFrame.size() != d_->frames || planes.size() != d_->frames ||
        static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) != d_->frameVoxels) {
        throw std::logic_error("DicomPixels::copyFrames: frames do not match the volume");
    }
    for (const std::size_t k : sliceOfFrame) {
        if (k >= static_cast<std::size_t>(dims.z)) {
            throw std::logic_error("DicomPixels::copyFrames: slice index out of range");
        }
    }
    const gdcm::PixelFormat& pf = d_->format;
    StoredTransform t;
    const unsigned allocated = pf.GetBitsAllocated();
    const unsigned stored = pf.GetBitsStored();
    t.isSigned = pf.GetPixelRepresentation() == 1;
    t.bits = stored;
    if (d_->raw && stored > 0 && stored < allocated && allocated <= 32) {
        t.mask = true;
        const int shift = static_cast<int>(pf.GetHighBit()) + 1 - static_cast<int>(stored);
        t.shift = shift > 0 ? static_cast<unsigned>(shift) : 0U;
    }
    if (d_->monochrome1) {
        t.invert = true;
        const unsigned bits = stored > 0 && stored <= allocated ? stored : allocated;
        t.invertBase = t.isSigned ? -1 : (std::int64_t{1} << std::min(bits, 62U)) - 1;
    }
    const std::size_t voxels = d_->frameVoxels;
    const std::size_t outBytes = voxelBytes(out.type());
    const std::size_t pixelSize = pf.GetPixelSize();
    for (std::size_t f = 0; f < d_->frames; ++f) {
        const char* src = d_->buffer.data() + f * voxels * pixelSize;
        std::byte* dst = out.bytes().data() + sliceOfFrame[f] * voxels * outBytes;
        const Rescale& r = planes[f].rescale;
        // The buffer is only char-aligned: copy each frame into a typed buffer first.
        const auto run = [&]<typename T>(T*) {
            std::vector<T> typed(voxels);
            std::memcpy(typed.data(), src, voxels * sizeof(T));
            if (plan.realUnits && voxels > 0) {
                const auto [lo, hi] = storedRange(typed.data(), voxels, t);
                checkRescale(d_->file, r, lo, hi, kDicomRescaleFields);
            }
            convertFrame<T>(typed.data(), voxels, t, out.type(), plan.realUnits, r, dst);
        };
        switch (pf.GetScalarType()) {
        case gdcm::PixelFormat::UINT8:
            run(static_cast<std::uint8_t*>(nullptr));
            break;
        case gdcm::PixelFormat::INT8:
            run(static_cast<std::int8_t*>(nullptr));
            break;
        case gdcm::PixelFormat::UINT16:
            run(static_cast<std::uint16_t*>(nullptr));
            break;
        case gdcm::PixelFormat::INT16:
            run(static_cast<std::int16_t*>(nullptr));
            break;
        case gdcm::PixelFormat::UINT32:
            run(static_cast<std::uint32_t*>(nullptr));
            break;
        case gdcm::PixelFormat::INT32:
            run(static_cast<std::int32_t*>(nullptr));
            break;
        case gdcm::PixelFormat::FLOAT32:
            run(static_cast<float*>(nullptr));
            break;
        case gdcm::PixelFormat::FLOAT64:
            run(static_cast<double*>(nullptr));
            break;
        default:
            throw ScanError(d_->file, "unsupported pixel format");
        }
    }
}

} // namespace steerseg::scan
