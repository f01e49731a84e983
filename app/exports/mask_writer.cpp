// Masks as NIfTI-1 (.nii, .nii.gz) or gzip NRRD (.nrrd), on the scan's own grid and world
// coordinates, so they overlay it in ITK-SNAP and 3D Slicer.
#include "exports/mask_writer.hpp"

#include "files/file_write.hpp"
#include "model/file_name.hpp"
#include "scan/affine.hpp"
#include "scan/load_checks.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <nifti2_io.h>
#include <string>

namespace steerseg::exports {

namespace {

// Appends the voxels as 0/1 bytes in pieces, so that no second full-size copy is made.
void appendMask(files::GzipWriter& writer, std::span<const std::uint8_t> mask) {
    std::array<std::byte, 64 * 1024> chunk{};
    for (std::size_t at = 0; at < mask.size(); at += chunk.size()) {
        const std::size_t n = std::min(chunk.size(), mask.size() - at);
        for (std::size_t k = 0; k < n; ++k) {
            chunk[k] = mask[at + k] != 0 ? std::byte{1} : std::byte{0};
        }
        writer.append(std::span(chunk).first(n));
    }
}

std::vector<std::byte> binaryMask(std::span<const std::uint8_t> mask) {
    std::vector<std::byte> out(mask.size());
    std::transform(mask.begin(), mask.end(), out.begin(),
                   [](std::uint8_t v) { return v != 0 ? std::byte{1} : std::byte{0}; });
    return out;
}

// NIfTI-1 header (348 bytes) plus the 4-byte "no extensions" flag; data follows at 352.
std::array<std::byte, 352> niftiHeader(const Geometry& g) {
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
    std::strncpy(h.descrip, "steerseg mask", sizeof h.descrip - 1);
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

std::string number(double v) {
    std::array<char, 32> text{};
    const auto result = std::to_chars(text.data(), text.data() + text.size(), v);
    return std::string(text.data(), result.ptr);
}

std::string vectorText(const glm::dvec3& v) {
    return "(" + number(v.x) + "," + number(v.y) + "," + number(v.z) + ")";
}

// `comment` says what the voxels hold; `keyValues` ("key:=value" lines) follow the fields.
std::string nrrdHeader(const Geometry& g, const std::string& comment,
                       const std::string& keyValues) {
    const scan::Affine lps = scan::affineOf(g);
    std::string h = "NRRD0004\n"
                    "# Complete NRRD file format specification at:\n"
                    "# http://teem.sourceforge.net/nrrd/format.html\n"
                    "# " +
                    comment +
                    "\n"
                    "type: uint8\n"
                    "dimension: 3\n"
                    "space: left-posterior-superior\n";
    h += "sizes: " + std::to_string(g.dims.x) + " " + std::to_string(g.dims.y) + " " +
         std::to_string(g.dims.z) + "\n";
    h += "space directions: " + vectorText(lps.linear[0]) + " " + vectorText(lps.linear[1]) + " " +
         vectorText(lps.linear[2]) + "\n";
    h += "kinds: domain domain domain\n"
         "endian: little\n"
         "encoding: gzip\n";
    h += "space origin: " + vectorText(lps.offset) + "\n";
    return h + keyValues + "\n";
}

// Slicer writes its colours with six decimals, components 0..1.
std::string colorText(const glm::dvec3& c) {
    std::array<char, 64> text{};
    std::snprintf(text.data(), text.size(), "%.6f %.6f %.6f", c.r, c.g, c.b);
    return text.data();
}

// The inclusive voxel index box of the inside voxels, "i0 i1 j0 j1 k0 k1"; Slicer's empty
// extent "0 -1 0 -1 0 -1" when nothing is inside.
std::string extentText(const glm::ivec3& dims, std::span<const std::uint8_t> mask) {
    glm::ivec3 lo = dims;
    glm::ivec3 hi(-1);
    std::size_t n = 0;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i, ++n) {
                if (mask[n] != 0) {
                    lo = glm::min(lo, glm::ivec3(i, j, k));
                    hi = glm::max(hi, glm::ivec3(i, j, k));
                }
            }
        }
    }
    if (hi.x < 0) {
        return "0 -1 0 -1 0 -1";
    }
    std::string out;
    for (int a = 0; a < 3; ++a) {
        out += (a == 0 ? "" : " ") + std::to_string(lo[a]) + " " + std::to_string(hi[a]);
    }
    return out;
}

// A header value is one line, and Slicer splits lists on '|': a name or id may hold neither;
// tags are such a list.
std::string headerValue(const std::filesystem::path& path, const std::string& what,
                        const std::string& value, bool list = false) {
    if (value.find_first_of(list ? "\r\n" : "\r\n|") != std::string::npos) {
        throw files::WriteError(path,
                                "the segment's " + what + " must not hold a line break or '|'");
    }
    return value;
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

void writeMask(const std::filesystem::path& path, const Geometry& geometry,
               std::span<const std::uint8_t> mask) {
    checkMaskSize(path, geometry, mask);
    const std::string name = model::lowerFileName(path);
    if (model::hasSuffix(name, ".nii.gz") || model::hasSuffix(name, ".nii")) {
        if (std::max({geometry.dims.x, geometry.dims.y, geometry.dims.z}) > 32767) {
            throw files::WriteError(path,
                                    "NIfTI-1 holds at most 32767 voxels per axis; write .nrrd");
        }
        const auto header = niftiHeader(geometry);
        if (model::hasSuffix(name, ".gz")) {
            files::GzipWriter writer; // one gzip member holds header and voxels
            writer.append(header);
            appendMask(writer, mask);
            files::writeFileAtomically(path, {writer.finish()});
        } else {
            const std::vector<std::byte> voxels = binaryMask(mask);
            files::writeFileAtomically(path, {header, voxels});
        }
        return;
    }
    if (model::hasSuffix(name, ".nrrd")) {
        const std::string header = nrrdHeader(geometry, "steerseg mask: 1 inside, 0 outside", "");
        files::GzipWriter writer;
        appendMask(writer, mask);
        files::writeFileAtomically(path, {std::as_bytes(std::span(header)), writer.finish()});
        return;
    }
    throw files::WriteError(path, "unsupported mask format (use .nii.gz, .nii or .nrrd)");
}

void writeSegmentation(const std::filesystem::path& path, const Geometry& geometry,
                       std::span<const std::uint8_t> mask, const SegmentInfo& segment) {
    checkMaskSize(path, geometry, mask);
    if (segment.label < 1 || segment.label > 255) {
        throw files::WriteError(path, "the segment's label value must be within 1..255 (got " +
                                          std::to_string(segment.label) + ")");
    }
    if (segment.name.empty()) {
        throw files::WriteError(path, "the segment needs a name");
    }
    for (int c = 0; c < 3; ++c) {
        if (!(segment.color[c] >= 0.0 && segment.color[c] <= 1.0)) {
            throw files::WriteError(path, "the segment's colour components must be within 0..1");
        }
    }
    const std::string name = headerValue(path, "name", segment.name);
    const std::string id = headerValue(path, "id", segment.id.empty() ? name : segment.id);
    const std::string tags = headerValue(path, "tags", segment.tags, true);
    // The keys and values 3D Slicer's segmentation storage node writes for one segment in one
    // layer (vtkMRMLSegmentationStorageNode): the master representation is this labelmap, on
    // the reference image's own extent.
    std::string keys;
    keys += "Segment0_Color:=" + colorText(segment.color) + "\n";
    keys += "Segment0_ColorAutoGenerated:=0\n";
    keys += "Segment0_Extent:=" + extentText(geometry.dims, mask) + "\n";
    keys += "Segment0_ID:=" + id + "\n";
    keys += "Segment0_LabelValue:=" + std::to_string(segment.label) + "\n";
    keys += "Segment0_Layer:=0\n";
    keys += "Segment0_Name:=" + name + "\n";
    keys += "Segment0_NameAutoGenerated:=0\n";
    keys += "Segment0_Tags:=" + (tags.empty() || tags.back() == '|' ? tags : tags + "|") + "\n";
    keys += "Segmentation_ContainedRepresentationNames:=Binary labelmap|\n";
    keys += "Segmentation_MasterRepresentation:=Binary labelmap\n";
    keys += "Segmentation_ReferenceImageExtentOffset:=0 0 0\n";
    const std::string header = nrrdHeader(
        geometry, "steerseg segmentation: the segment's label value inside, 0 outside", keys);
    files::GzipWriter writer;
    std::array<std::byte, 64 * 1024> chunk{};
    const auto label = static_cast<std::byte>(segment.label);
    for (std::size_t at = 0; at < mask.size(); at += chunk.size()) {
        const std::size_t n = std::min(chunk.size(), mask.size() - at);
        for (std::size_t k = 0; k < n; ++k) {
            chunk[k] = mask[at + k] != 0 ? label : std::byte{0};
        }
        writer.append(std::span(chunk).first(n));
    }
    files::writeFileAtomically(path, {std::as_bytes(std::span(header)), writer.finish()});
}

} // namespace steerseg::exports
