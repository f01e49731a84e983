#include "support/io_test_files.hpp"

#include "scan/affine.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <nifti2_io.h>

namespace steerseg::test {

Geometry obliqueGeometry(const glm::ivec3& dims) {
    const double a = 0.5; // radians about an oblique axis
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));
    const double c = std::cos(a);
    const double s = std::sin(a);
    glm::dmat3 r(c);
    r += (1.0 - c) * glm::outerProduct(axis, axis);
    const glm::dmat3 cross(glm::dvec3(0, axis.z, -axis.y), glm::dvec3(-axis.z, 0, axis.x),
                           glm::dvec3(axis.y, -axis.x, 0));
    r += s * cross;
    r[1] = -r[1]; // a left-handed grid too
    Geometry g;
    g.dims = dims;
    g.spacing = {0.75, 1.25, 2.5};
    g.origin = {-12.5, 40.25, 7.0};
    g.direction = r;
    return g;
}

double pattern(int i, int j, int k) {
    return static_cast<double>((i + 3 * j + 7 * k) % 251);
}

std::vector<double> patternValues(const glm::ivec3& dims) {
    std::vector<double> v;
    for (int k = 0; k < dims.z; ++k) {
        for (int j = 0; j < dims.y; ++j) {
            for (int i = 0; i < dims.x; ++i) {
                v.push_back(pattern(i, j, k));
            }
        }
    }
    return v;
}

namespace {

template <typename T> void append(std::vector<std::byte>& out, T value, bool bigEndian) {
    std::array<std::byte, sizeof(T)> b{};
    std::memcpy(b.data(), &value, sizeof(T));
    if (bigEndian) {
        std::reverse(b.begin(), b.end());
    }
    out.insert(out.end(), b.begin(), b.end());
}

} // namespace

std::vector<std::byte> encodeSamples(const std::vector<double>& values, const std::string& type,
                                     bool bigEndian) {
    std::vector<std::byte> out;
    for (const double v : values) {
        if (type == "uint8") {
            append(out, static_cast<std::uint8_t>(v), bigEndian);
        } else if (type == "int8") {
            append(out, static_cast<std::int8_t>(v), bigEndian);
        } else if (type == "int16") {
            append(out, static_cast<std::int16_t>(v), bigEndian);
        } else if (type == "uint16") {
            append(out, static_cast<std::uint16_t>(v), bigEndian);
        } else if (type == "int32") {
            append(out, static_cast<std::int32_t>(v), bigEndian);
        } else if (type == "uint32") {
            append(out, static_cast<std::uint32_t>(v), bigEndian);
        } else if (type == "float32") {
            append(out, static_cast<float>(v), bigEndian);
        } else if (type == "float64") {
            append(out, v, bigEndian);
        } else {
            throw std::invalid_argument("unknown sample type " + type);
        }
    }
    return out;
}

void writeFile(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) {
        throw std::runtime_error("cannot write " + path.string());
    }
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    writeFile(path, concat(text, {}));
}

std::vector<std::byte> concat(const std::string& text, const std::vector<std::byte>& bytes) {
    std::vector<std::byte> out(text.size());
    std::transform(text.begin(), text.end(), out.begin(),
                   [](char c) { return static_cast<std::byte>(c); });
    out.insert(out.end(), bytes.begin(), bytes.end());
    return out;
}

namespace {

template <typename Header> void fillNifti(Header& h, const Geometry& g, const NiftiOptions& o) {
    h.dim[0] = o.volumes > 1 ? 4 : 3;
    for (int a = 0; a < 3; ++a) {
        h.dim[a + 1] = g.dims[a];
        h.pixdim[a + 1] = g.spacing[a];
    }
    h.dim[4] = o.volumes;
    h.pixdim[4] = 1;
    h.datatype = static_cast<short>(o.datatype);
    h.scl_slope = o.slope;
    h.scl_inter = o.inter;
    h.xyzt_units = NIFTI_UNITS_MM;
    h.sform_code = static_cast<short>(o.sformCode);
    h.qform_code = static_cast<short>(o.qformCode);
    const scan::Affine ras = scan::flipRasLps(scan::affineOf(g));
    nifti_dmat44 m{};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            m.m[r][c] = ras.linear[c][r];
        }
        m.m[r][3] = ras.offset[r];
        h.srow_x[r] = m.m[0][r];
        h.srow_y[r] = m.m[1][r];
        h.srow_z[r] = m.m[2][r];
    }
    h.srow_x[3] = m.m[0][3];
    h.srow_y[3] = m.m[1][3];
    h.srow_z[3] = m.m[2][3];
    m.m[3][3] = 1.0;
    double qb = 0, qc = 0, qd = 0, qx = 0, qy = 0, qz = 0, dx = 0, dy = 0, dz = 0, qfac = 1;
    nifti_dmat44_to_quatern(m, &qb, &qc, &qd, &qx, &qy, &qz, &dx, &dy, &dz, &qfac);
    h.quatern_b = qb;
    h.quatern_c = qc;
    h.quatern_d = qd;
    h.qoffset_x = qx;
    h.qoffset_y = qy;
    h.qoffset_z = qz;
    h.pixdim[0] = qfac;
}

template <typename T> void assignNarrow(T& dst, double v) {
    dst = static_cast<T>(v);
}

} // namespace

std::vector<std::byte> niftiFile(const Geometry& g, const std::vector<std::byte>& data,
                                 const NiftiOptions& o) {
    std::vector<std::byte> out;
    if (o.version == 2) {
        nifti_2_header h{};
        h.sizeof_hdr = 540;
        std::memcpy(h.magic, "n+2\0\r\n\032\n", 8);
        fillNifti(h, g, o);
        h.bitpix = 8;
        h.vox_offset = 544;
        if (o.bigEndian) {
            swap_nifti_header(&h, 2);
        }
        out.resize(544);
        std::memcpy(out.data(), &h, sizeof h);
    } else {
        // nifti_1_header holds floats and shorts: fill a NIfTI-2 header and narrow it.
        nifti_2_header wide{};
        fillNifti(wide, g, o);
        nifti_1_header h{};
        h.sizeof_hdr = 348;
        std::memcpy(h.magic, "n+1", 4);
        for (int n = 0; n < 8; ++n) {
            assignNarrow(h.dim[n], static_cast<double>(wide.dim[n]));
            assignNarrow(h.pixdim[n], wide.pixdim[n]);
        }
        for (int n = 0; n < 4; ++n) {
            assignNarrow(h.srow_x[n], wide.srow_x[n]);
            assignNarrow(h.srow_y[n], wide.srow_y[n]);
            assignNarrow(h.srow_z[n], wide.srow_z[n]);
        }
        h.datatype = wide.datatype;
        h.bitpix = 8;
        h.vox_offset = 352;
        assignNarrow(h.scl_slope, wide.scl_slope);
        assignNarrow(h.scl_inter, wide.scl_inter);
        h.xyzt_units = static_cast<char>(wide.xyzt_units);
        h.sform_code = static_cast<short>(wide.sform_code);
        h.qform_code = static_cast<short>(wide.qform_code);
        assignNarrow(h.quatern_b, wide.quatern_b);
        assignNarrow(h.quatern_c, wide.quatern_c);
        assignNarrow(h.quatern_d, wide.quatern_d);
        assignNarrow(h.qoffset_x, wide.qoffset_x);
        assignNarrow(h.qoffset_y, wide.qoffset_y);
        assignNarrow(h.qoffset_z, wide.qoffset_z);
        if (o.bigEndian) {
            swap_nifti_header(&h, 1);
        }
        out.resize(352);
        std::memcpy(out.data(), &h, sizeof h);
    }
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::vector<std::byte> mghFile(const Geometry& g, int type, const std::vector<double>& values) {
    std::vector<std::byte> out;
    for (const int v : {1, g.dims.x, g.dims.y, g.dims.z, 1, type, 0}) {
        append(out, static_cast<std::int32_t>(v), true);
    }
    append(out, static_cast<std::int16_t>(1), true);
    const scan::Affine ras = scan::flipRasLps(scan::affineOf(g));
    for (int a = 0; a < 3; ++a) {
        append(out, static_cast<float>(g.spacing[a]), true);
    }
    for (int a = 0; a < 3; ++a) {
        for (int r = 0; r < 3; ++r) {
            append(out, static_cast<float>(ras.linear[a][r] / g.spacing[a]), true);
        }
    }
    const glm::dvec3 centre = ras.linear * (glm::dvec3(g.dims) / 2.0) + ras.offset;
    for (int r = 0; r < 3; ++r) {
        append(out, static_cast<float>(centre[r]), true);
    }
    out.resize(284);
    const char* types[] = {"uint8", "int32", "", "float32", "int16"};
    const auto data = encodeSamples(values, types[type], true);
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

void expectSameGeometry(const Geometry& a, const Geometry& b, double tolerance) {
    EXPECT_EQ(a.dims, b.dims);
    for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(a.spacing[r], b.spacing[r], tolerance) << "spacing " << r;
        EXPECT_NEAR(a.origin[r], b.origin[r], tolerance * 100.0) << "origin " << r;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(a.direction[c][r], b.direction[c][r], tolerance)
                << "direction row " << r << " column " << c;
        }
    }
}

glm::dvec3 worldCentroid(const Volume& v, double threshold) {
    glm::dvec3 sum(0.0);
    double count = 0.0;
    const auto d = v.dims();
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                if (v.valueAt(i, j, k) > threshold) {
                    sum += glm::dvec3(i, j, k);
                    count += 1.0;
                }
            }
        }
    }
    return v.geometry().indexToWorld(sum / std::max(count, 1.0));
}

} // namespace steerseg::test
