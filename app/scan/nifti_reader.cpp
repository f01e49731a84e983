// NIfTI-1 and NIfTI-2 (.nii, .nii.gz). nifticlib supplies the header layouts, byte swapping and
// the quaternion maths; the voxel data is read here, never by nifticlib, so that a hostile header
// cannot make it allocate what the file does not hold.
#include "scan/affine.hpp"
#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/readers.hpp"
#include "scan/sample_decode.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstring>
#include <memory>
#include <nifti2_io.h>

namespace steerseg::scan {

namespace {

constexpr std::int32_t kNifti1HeaderSize = 348;
constexpr std::int32_t kNifti2HeaderSize = 540;

// The fields this reader uses, widened to NIfTI-2's types.
struct NiftiFields {
    int version = 1;
    std::int64_t dim[8] = {};
    double pixdim[8] = {};
    int datatype = 0;
    double voxOffset = 0.0;
    double sclSlope = 0.0;
    double sclInter = 0.0;
    int qformCode = 0;
    int sformCode = 0;
    double quatern[3] = {};
    double qoffset[3] = {};
    double srow[3][4] = {};
};

template <typename Header> void copyCommon(const Header& h, NiftiFields& f) {
    for (int n = 0; n < 8; ++n) {
        f.dim[n] = h.dim[n];
        f.pixdim[n] = static_cast<double>(h.pixdim[n]);
    }
    f.datatype = h.datatype;
    f.voxOffset = static_cast<double>(h.vox_offset);
    f.sclSlope = static_cast<double>(h.scl_slope);
    f.sclInter = static_cast<double>(h.scl_inter);
    f.qformCode = h.qform_code;
    f.sformCode = h.sform_code;
    f.quatern[0] = static_cast<double>(h.quatern_b);
    f.quatern[1] = static_cast<double>(h.quatern_c);
    f.quatern[2] = static_cast<double>(h.quatern_d);
    f.qoffset[0] = static_cast<double>(h.qoffset_x);
    f.qoffset[1] = static_cast<double>(h.qoffset_y);
    f.qoffset[2] = static_cast<double>(h.qoffset_z);
    for (int c = 0; c < 4; ++c) {
        f.srow[0][c] = static_cast<double>(h.srow_x[c]);
        f.srow[1][c] = static_cast<double>(h.srow_y[c]);
        f.srow[2][c] = static_cast<double>(h.srow_z[c]);
    }
}

// Reads and byte-swaps the header; returns its fields and the data's byte order.
NiftiFields readHeader(const std::filesystem::path& path, ByteSource& src, ByteOrder& order) {
    std::vector<std::byte> bytes = readUpTo(src, kNifti1HeaderSize);
    if (bytes.empty()) {
        throw ScanError(path, "the file is empty");
    }
    if (bytes.size() < static_cast<std::size_t>(kNifti1HeaderSize)) {
        throw ScanError(path, "too short for a NIfTI header (" + std::to_string(bytes.size()) +
                                  " bytes)");
    }
    std::int32_t sizeofHdr = 0;
    std::memcpy(&sizeofHdr, bytes.data(), 4);
    const auto swappedSize =
        static_cast<std::int32_t>(__builtin_bswap32(static_cast<std::uint32_t>(sizeofHdr)));
    const bool swapped = sizeofHdr != kNifti1HeaderSize && sizeofHdr != kNifti2HeaderSize;
    const std::int32_t size = swapped ? swappedSize : sizeofHdr;
    if (size != kNifti1HeaderSize && size != kNifti2HeaderSize) {
        throw ScanError(path, "not a NIfTI file (header size field is " +
                                  std::to_string(sizeofHdr) + ", expected 348 or 540)");
    }
    const bool nativeBig = std::endian::native == std::endian::big;
    order = (swapped != nativeBig) ? ByteOrder::Big : ByteOrder::Little;

    NiftiFields f;
    if (size == kNifti1HeaderSize) {
        nifti_1_header h{};
        std::memcpy(&h, bytes.data(), sizeof h);
        if (swapped) {
            swap_nifti_header(&h, 1);
        }
        if (std::memcmp(h.magic, "ni1", 4) == 0) {
            throw ScanError(path, "is a NIfTI header/image pair (.hdr/.img); steerseg reads "
                                  "single-file .nii or .nii.gz");
        }
        if (std::memcmp(h.magic, "n+1", 4) != 0) {
            throw ScanError(path, "not a NIfTI-1 file (no \"n+1\" magic; Analyze 7.5 is not "
                                  "supported)");
        }
        copyCommon(h, f);
        return f;
    }
    const std::vector<std::byte> rest = readUpTo(src, kNifti2HeaderSize - kNifti1HeaderSize);
    if (rest.size() < static_cast<std::size_t>(kNifti2HeaderSize - kNifti1HeaderSize)) {
        throw ScanError(path, "too short for a NIfTI-2 header");
    }
    bytes.insert(bytes.end(), rest.begin(), rest.end());
    nifti_2_header h{};
    std::memcpy(&h, bytes.data(), sizeof h);
    if (swapped) {
        swap_nifti_header(&h, 2);
    }
    if (std::memcmp(h.magic, "n+2", 4) != 0) {
        throw ScanError(path, std::memcmp(h.magic, "ni2", 4) == 0
                                  ? "is a NIfTI-2 header/image pair; steerseg reads single-file "
                                    ".nii or .nii.gz"
                                  : "not a NIfTI-2 file (no \"n+2\" magic)");
    }
    f.version = 2;
    copyCommon(h, f);
    return f;
}

SampleType sampleTypeOf(const std::filesystem::path& path, int datatype) {
    switch (datatype) {
    case NIFTI_TYPE_UINT8:
        return SampleType::UInt8;
    case NIFTI_TYPE_INT8:
        return SampleType::Int8;
    case NIFTI_TYPE_INT16:
        return SampleType::Int16;
    case NIFTI_TYPE_UINT16:
        return SampleType::UInt16;
    case NIFTI_TYPE_INT32:
        return SampleType::Int32;
    case NIFTI_TYPE_UINT32:
        return SampleType::UInt32;
    case NIFTI_TYPE_INT64:
        return SampleType::Int64;
    case NIFTI_TYPE_UINT64:
        return SampleType::UInt64;
    case NIFTI_TYPE_FLOAT32:
        return SampleType::Float32;
    case NIFTI_TYPE_FLOAT64:
        return SampleType::Float64;
    default:
        throw ScanError(path, "NIfTI datatype " + std::to_string(datatype) +
                                  " is not a scalar intensity type steerseg reads (RGB, "
                                  "complex and float128 are not supported)");
    }
}

// Spatial dims from dim[]; refuses 4D data with more than one volume.
glm::ivec3 spatialDims(const std::filesystem::path& path, const NiftiFields& f,
                       const ReadLimits& limits) {
    const std::int64_t ndim = f.dim[0];
    if (ndim < 1 || ndim > 7) {
        throw ScanError(path, "dim[0] = " + std::to_string(ndim) + " is not between 1 and 7");
    }
    glm::ivec3 dims(1);
    for (int a = 0; a < 3; ++a) {
        if (a < ndim) {
            const std::int64_t d = f.dim[a + 1];
            dims[a] = static_cast<int>(std::clamp<std::int64_t>(d, INT_MIN, INT_MAX));
        }
    }
    checkDims(path, dims, limits);
    std::int64_t volumes = 1;
    for (std::int64_t a = 4; a <= ndim; ++a) {
        const std::int64_t d = f.dim[a];
        if (d < 0) {
            throw ScanError(path, "dim[" + std::to_string(a) + "] = " + std::to_string(d) +
                                      " is negative");
        }
        volumes = d > 1 ? (volumes > INT_MAX / d ? INT_MAX : volumes * d) : volumes;
    }
    if (volumes > 1) {
        throw ScanError(path, "holds " + std::to_string(volumes) +
                                  " volumes (4D or more); steerseg segments one 3D volume: "
                                  "extract it first (e.g. fslroi in.nii.gz out.nii.gz 0 1)");
    }
    return dims;
}

// Index-to-RAS affine: the sform if set and not sheared, else the qform, else pixdim alone.
Affine rasAffine(const std::filesystem::path& path, const NiftiFields& f, int ndim) {
    Affine a;
    const bool sformUsable = [&] {
        if (f.sformCode <= 0) {
            return false;
        }
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) {
                a.linear[c][r] = f.srow[r][c];
            }
            a.offset[c] = f.srow[c][3];
        }
        return hasOrthogonalColumns(a.linear);
    }();
    if (sformUsable) {
        return a;
    }
    if (f.sformCode > 0 && f.qformCode <= 0) {
        throw ScanError(path, "the sform is sheared or degenerate and there is no qform");
    }
    // Unused trailing pixdims are often 0; a 2D image is one slice of 1 mm.
    const double dz = ndim >= 3 ? f.pixdim[3] : 1.0;
    const double dy = ndim >= 2 ? f.pixdim[2] : 1.0;
    for (const double d : {f.pixdim[1], dy, dz}) {
        if (!(d > 0.0) || !std::isfinite(d)) {
            throw ScanError(path, "pixdim " + std::to_string(f.pixdim[1]) + " x " +
                                      std::to_string(dy) + " x " + std::to_string(dz) +
                                      " is not positive and finite");
        }
    }
    if (f.qformCode > 0) {
        // NIfTI: qfac = pixdim[0] < 0 ? -1 : 1 (a left-handed grid flips k).
        const double qfac = f.pixdim[0] < 0.0 ? -1.0 : 1.0;
        const nifti_dmat44 m =
            nifti_quatern_to_dmat44(f.quatern[0], f.quatern[1], f.quatern[2], f.qoffset[0],
                                    f.qoffset[1], f.qoffset[2], f.pixdim[1], dy, dz, qfac);
        for (int c = 0; c < 3; ++c) {
            for (int r = 0; r < 3; ++r) {
                a.linear[c][r] = m.m[r][c];
            }
            a.offset[c] = m.m[c][3];
        }
        return a;
    }
    a.linear = glm::dmat3(1.0);
    a.linear[0][0] = f.pixdim[1];
    a.linear[1][1] = dy;
    a.linear[2][2] = dz;
    a.offset = glm::dvec3(0.0);
    return a;
}

} // namespace

Volume readNiftiFrom(const std::filesystem::path& path, SeekableSource& file,
                     const ReadLimits& limits, std::string& format) {
    std::unique_ptr<GzipSource> gzip;
    if (startsWithGzipMagic(file)) {
        gzip = std::make_unique<GzipSource>(path, file);
    }
    ByteSource& src = gzip ? static_cast<ByteSource&>(*gzip) : file;

    ByteOrder order = ByteOrder::Little;
    const NiftiFields f = readHeader(path, src, order);
    format = f.version == 2 ? "nifti2" : "nifti";
    const glm::ivec3 dims = spatialDims(path, f, limits);
    const SampleType type = sampleTypeOf(path, f.datatype);
    const auto ndim = static_cast<int>(f.dim[0]);
    const Geometry geometry = geometryFromAffine(path, flipRasLps(rasAffine(path, f, ndim)), dims);

    const std::int32_t headerSize = f.version == 2 ? kNifti2HeaderSize : kNifti1HeaderSize;
    if (!std::isfinite(f.voxOffset) || f.voxOffset < headerSize || f.voxOffset > 0x1p62) {
        throw ScanError(path, "vox_offset " + std::to_string(f.voxOffset) +
                                  " does not point past the header");
    }
    // Extensions between header and data are skipped unread.
    const auto skip =
        static_cast<std::uint64_t>(f.voxOffset) - static_cast<std::uint64_t>(headerSize);
    if (skipBytes(src, skip) < skip) {
        throw ScanError(path, "vox_offset " +
                                  std::to_string(static_cast<std::uint64_t>(f.voxOffset)) +
                                  " lies beyond the end of the file");
    }
    const std::uint64_t dataBytes = geometry.voxelCount() * sampleBytes(type);
    const std::string expected = expectedDataText("header", dims, type);
    checkDataFits(path, dataBytes, src, limits, expected);
    const std::vector<std::byte> raw = readExactly(path, src, dataBytes, expected);
    Volume volume = decodeVolume(path, geometry, type, order, raw);

    // scl_slope 0 means "no scaling" in NIfTI. nifticlib also reads a slope or intercept that is
    // not finite as "no scaling"; we refuse it, as one that takes the data past float32: either
    // way the intensities (and T, eps) would be in units the file did not mean.
    if (f.sclSlope != 0.0) {
        volume.setRescale({f.sclSlope, f.sclInter});
        checkRescale(path, volume, "scl_slope/scl_inter");
    }
    return volume;
}

Volume readNifti(const std::filesystem::path& path, const ReadLimits& limits, std::string& format) {
    FileSource file(path);
    return readNiftiFrom(path, file, limits, format);
}

} // namespace steerseg::scan
