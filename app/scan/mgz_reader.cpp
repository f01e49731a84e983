// FreeSurfer MGH / MGZ: a big-endian 284-byte header, then width*height*depth*frames voxels
// (gzip-compressed as a whole for .mgz). Geometry is RAS around the volume's centre.
#include "scan/affine.hpp"
#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/readers.hpp"
#include "scan/sample_decode.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <memory>

namespace steerseg::scan {

namespace {

constexpr std::size_t kMghHeaderBytes = 284;

std::int32_t be32(const std::byte* p) {
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) {
        v = (v << 8) | std::to_integer<std::uint32_t>(p[k]);
    }
    return static_cast<std::int32_t>(v);
}

double beFloat(const std::byte* p) {
    return static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(be32(p))));
}

SampleType mghType(const std::filesystem::path& path, std::int32_t type) {
    switch (type) {
    case 0:
        return SampleType::UInt8;
    case 1:
        return SampleType::Int32;
    case 3:
        return SampleType::Float32;
    case 4:
        return SampleType::Int16;
    default:
        throw ScanError(path, "MGH voxel type " + std::to_string(type) +
                                  " is not supported (0 uchar, 1 int, 3 float, 4 short are)");
    }
}

} // namespace

Volume readMgzFrom(const std::filesystem::path& path, SeekableSource& file,
                   const ReadLimits& limits) {
    std::unique_ptr<GzipSource> gzip;
    if (startsWithGzipMagic(file)) {
        gzip = std::make_unique<GzipSource>(path, file);
    }
    ByteSource& src = gzip ? static_cast<ByteSource&>(*gzip) : file;

    const std::vector<std::byte> h = readUpTo(src, kMghHeaderBytes);
    if (h.empty()) {
        throw ScanError(path, "the file is empty");
    }
    if (h.size() < kMghHeaderBytes) {
        throw ScanError(path,
                        "too short for an MGH header (" + std::to_string(h.size()) + " bytes)");
    }
    const std::int32_t version = be32(h.data());
    if (version != 1) {
        throw ScanError(path, "not an MGH/MGZ file (version field is " + std::to_string(version) +
                                  ", expected 1)");
    }
    const glm::ivec3 dims(be32(h.data() + 4), be32(h.data() + 8), be32(h.data() + 12));
    checkDims(path, dims, limits);
    const std::int32_t frames = be32(h.data() + 16);
    if (frames != 1) {
        throw ScanError(path, "holds " + std::to_string(frames) +
                                  " frames; steerseg segments one 3D volume (extract it with "
                                  "mri_convert --frame 0)");
    }
    const SampleType type = mghType(path, be32(h.data() + 20));
    const auto goodRas =
        static_cast<std::int16_t>(std::to_integer<int>(h[28]) << 8 | std::to_integer<int>(h[29]));

    // Without goodRASflag FreeSurfer assumes 1 mm coronal slices (LIA) centred on the origin.
    glm::dvec3 spacing(1.0);
    glm::dmat3 mdc(glm::dvec3(-1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
    glm::dvec3 centre(0.0);
    if (goodRas > 0) {
        for (int a = 0; a < 3; ++a) {
            spacing[a] = beFloat(h.data() + 30 + 4 * a);
            for (int r = 0; r < 3; ++r) {
                mdc[a][r] = beFloat(h.data() + 42 + 12 * a + 4 * r); // x_r x_a x_s, y_r ...
            }
            centre[a] = beFloat(h.data() + 78 + 4 * a);
        }
    }
    // vox2ras = [Mdc*D | c_ras - Mdc*D*(dims/2)]: c_ras sits at voxel index dims/2.
    Affine ras;
    for (int a = 0; a < 3; ++a) {
        ras.linear[a] = mdc[a] * spacing[a];
    }
    ras.offset = centre - ras.linear * (glm::dvec3(dims) / 2.0);
    const Geometry geometry = geometryFromAffine(path, flipRasLps(ras), dims);

    const std::uint64_t dataBytes = geometry.voxelCount() * sampleBytes(type);
    const std::string expected = expectedDataText("header", dims, type);
    checkDataFits(path, dataBytes, src, limits, expected);
    const auto raw = readExactly(path, src, dataBytes, expected);
    return decodeVolume(path, geometry, type, ByteOrder::Big, raw);
}

Volume readMgz(const std::filesystem::path& path, const ReadLimits& limits) {
    FileSource file(path);
    return readMgzFrom(path, file, limits);
}

} // namespace steerseg::scan
