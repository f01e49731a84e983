// Masks and label maps as NIfTI-1 (.nii, .nii.gz) or gzip NRRD (.nrrd), on the scan's own grid and
// world coordinates, so they overlay it in ITK-SNAP and 3D Slicer.
#include "exports/mask_writer.hpp"

#include "exports/nrrd_header.hpp"
#include "files/file_write.hpp"
#include "model/file_name.hpp"
#include "scan/affine.hpp"
#include "scan/load_checks.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <nifti2_io.h>
#include <string>

namespace steerseg::exports {

namespace {

// Appends the voxels in pieces, so that no second full-size copy is made: 0/1 for a mask
// (any non-zero is inside), the values themselves for a label map.
void appendVoxels(files::GzipWriter& writer, std::span<const std::uint8_t> voxels, bool binary) {
    std::array<std::byte, 64 * 1024> chunk{};
    for (std::size_t at = 0; at < voxels.size(); at += chunk.size()) {
        const std::size_t n = std::min(chunk.size(), voxels.size() - at);
        for (std::size_t k = 0; k < n; ++k) {
            const std::uint8_t v = voxels[at + k];
            chunk[k] = static_cast<std::byte>(binary && v != 0 ? 1 : v);
        }
        writer.append(std::span(chunk).first(n));
    }
}

std::vector<std::byte> voxelBytes(std::span<const std::uint8_t> voxels, bool binary) {
    std::vector<std::byte> out(voxels.size());
    std::transform(voxels.begin(), voxels.end(), out.begin(), [binary](std::uint8_t v) {
        return static_cast<std::byte>(binary && v != 0 ? 1 : v);
    });
    return out;
}

// NIfTI-1 header (348 bytes) plus the 4-byte "no extensions" flag; data follows at 352.
std::array<std::byte, 352> niftiHeader(const Geometry& g, const char* description) {
    nifti_1_header h{};
    h.sizeof_hdr = 348;
    h.dim[0] = 3;
    for (int a = 0; a < 3; ++a) {
        h.dim[a + 1] = static_cast<short>(g.dims[a]);
        h.pixdim[a + 1] = static_cast<float>(g.spacing[a]);
    }
    for (int a = 4; a < 8; ++a) {
        h.dim[a] = 1;
        h.pixdim[a] = 1.0f;
    }
    h.datatype = NIFTI_TYPE_UINT8;
    h.bitpix = 8;
    h.vox_offset = 352.0f;
    h.scl_slope = 0.0f; // no scaling: the stored 0/1 are the values
    h.scl_inter = 0.0f;
    h.xyzt_units = NIFTI_UNITS_MM;
    h.qform_code = NIFTI_XFORM_SCANNER_ANAT;
    h.sform_code = NIFTI_XFORM_SCANNER_ANAT;
    std::strncpy(h.descrip, description, sizeof h.descrip - 1);
    std::memcpy(h.magic, "n+1", 4);

    const scan::Affine ras = scan::flipRasLps(scan::affineOf(g));
    nifti_dmat44 m{};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            m.m[r][c] = ras.linear[c][r];
        }
        m.m[r][3] = ras.offset[r];
    }
    m.m[3][3] = 1.0;
    float* rows[3] = {h.srow_x, h.srow_y, h.srow_z};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            rows[r][c] = static_cast<float>(m.m[r][c]);
        }
    }
    double qb = 0, qc = 0, qd = 0, qx = 0, qy = 0, qz = 0, dx = 0, dy = 0, dz = 0, qfac = 1;
    nifti_dmat44_to_quatern(m, &qb, &qc, &qd, &qx, &qy, &qz, &dx, &dy, &dz, &qfac);
    h.quatern_b = static_cast<float>(qb);
    h.quatern_c = static_cast<float>(qc);
    h.quatern_d = static_cast<float>(qd);
    h.qoffset_x = static_cast<float>(qx);
    h.qoffset_y = static_cast<float>(qy);
    h.qoffset_z = static_cast<float>(qz);
    h.pixdim[0] = static_cast<float>(qfac);

    std::array<std::byte, 352> out{};
    std::memcpy(out.data(), &h, sizeof h);
    return out;
}

} // namespace

void checkMaskSize(const std::filesystem::path& path, const Geometry& geometry,
                   std::span<const std::uint8_t> mask) {
    scan::checkGeometry(path, geometry);
    if (geometry.voxelCount() == 0 || mask.size() != geometry.voxelCount()) {
        throw files::WriteError(path, "mask has " + std::to_string(mask.size()) +
                                          " voxels but the grid " + dimsText(geometry.dims) +
                                          " has " + std::to_string(geometry.voxelCount()));
    }
}

namespace {

// A mask (`binary`) or a label map in the format the extension names.
void writeVoxels(const std::filesystem::path& path, const Geometry& geometry,
                 std::span<const std::uint8_t> voxels, bool binary) {
    checkMaskSize(path, geometry, voxels);
    const std::string name = model::lowerFileName(path);
    if (model::hasSuffix(name, ".nii.gz") || model::hasSuffix(name, ".nii")) {
        if (std::max({geometry.dims.x, geometry.dims.y, geometry.dims.z}) > 32767) {
            throw files::WriteError(path,
                                    "NIfTI-1 holds at most 32767 voxels per axis; write .nrrd");
        }
        const auto header = niftiHeader(geometry, binary ? "steerseg mask" : "steerseg label map");
        if (model::hasSuffix(name, ".gz")) {
            files::GzipWriter writer; // one gzip member holds header and voxels
            writer.append(header);
            appendVoxels(writer, voxels, binary);
            files::writeFileAtomically(path, {writer.finish()});
        } else {
            const std::vector<std::byte> bytes = voxelBytes(voxels, binary);
            files::writeFileAtomically(path, {header, bytes});
        }
        return;
    }
    if (model::hasSuffix(name, ".nrrd")) {
        const std::string header =
            nrrdHeader(geometry,
                       binary ? "steerseg mask: 1 inside, 0 outside"
                              : "steerseg label map: a structure's label inside, 0 outside",
                       "");
        files::GzipWriter writer;
        appendVoxels(writer, voxels, binary);
        files::writeFileAtomically(path, {std::as_bytes(std::span(header)), writer.finish()});
        return;
    }
    throw files::WriteError(path, "unsupported mask format (use .nii.gz, .nii or .nrrd)");
}

} // namespace

void writeMask(const std::filesystem::path& path, const Geometry& geometry,
               std::span<const std::uint8_t> mask) {
    writeVoxels(path, geometry, mask, true);
}

void writeLabelMap(const std::filesystem::path& path, const Geometry& geometry,
                   std::span<const std::uint8_t> labels) {
    writeVoxels(path, geometry, labels, false);
}

} // namespace steerseg::exports
