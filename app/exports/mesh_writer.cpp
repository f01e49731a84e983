#include "exports/mesh_writer.hpp"

#include "files/file_write.hpp"
#include "model/file_name.hpp"
#include "scan/scan_reader.hpp"

#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace steerseg::exports {

namespace {

// Little-endian bytes whatever the host's order (both formats fix it).
class ByteWriter {
  public:
    void u8(std::uint8_t v) { bytes_.push_back(static_cast<std::byte>(v)); }
    void u16(std::uint16_t v) { le(v); }
    void u32(std::uint32_t v) { le(v); }
    void f32(double v) { le(std::bit_cast<std::uint32_t>(static_cast<float>(v))); }
    void vec(const glm::dvec3& v) {
        f32(v.x);
        f32(v.y);
        f32(v.z);
    }
    void text(const std::string& s) {
        const auto* p = reinterpret_cast<const std::byte*>(s.data());
        bytes_.insert(bytes_.end(), p, p + s.size());
    }
    void reserve(std::size_t n) { bytes_.reserve(n); }
    [[nodiscard]] std::span<const std::byte> bytes() const { return bytes_; }

  private:
    template <typename T> void le(T v) {
        for (std::size_t b = 0; b < sizeof(T); ++b) {
            bytes_.push_back(static_cast<std::byte>((v >> (8 * b)) & 0xffu));
        }
    }
    std::vector<std::byte> bytes_;
};

void checkWritable(const std::filesystem::path& path, const SurfaceMesh& mesh) {
    if (mesh.empty()) {
        throw files::WriteError(path,
                                "the surface is empty (nothing is inside the segmentation), so no "
                                "mesh was written");
    }
    if (mesh.triangles.size() > std::numeric_limits<std::uint32_t>::max() ||
        mesh.vertices.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw files::WriteError(path, "the surface has " + std::to_string(mesh.triangles.size()) +
                                          " triangles, more than the format can count");
    }
}

glm::dvec3 unitNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    // A sliver whose crossing sat exactly on a voxel centre has no direction of its own.
    return length > 0.0 ? n / length : glm::dvec3(0.0);
}

} // namespace

std::optional<MeshFormat> meshFormatFor(const std::filesystem::path& path) {
    const std::string name = model::lowerFileName(path);
    if (model::hasSuffix(name, ".stl")) {
        return MeshFormat::Stl;
    }
    if (model::hasSuffix(name, ".ply")) {
        return MeshFormat::Ply;
    }
    return std::nullopt;
}

void writeStl(const std::filesystem::path& path, const SurfaceMesh& mesh) {
    checkWritable(path, mesh);
    ByteWriter out;
    out.reserve(84 + 50 * mesh.triangles.size());
    // Must not start with "solid", which readers take for ASCII STL.
    std::string header = "steerseg surface, LPS mm (patient coordinates: x left, y posterior, "
                         "z superior)";
    header.resize(80, ' ');
    out.text(header);
    out.u32(static_cast<std::uint32_t>(mesh.triangles.size()));
    for (const auto& t : mesh.triangles) {
        const glm::dvec3& a = mesh.vertices[t[0]];
        const glm::dvec3& b = mesh.vertices[t[1]];
        const glm::dvec3& c = mesh.vertices[t[2]];
        out.vec(unitNormal(a, b, c));
        out.vec(a);
        out.vec(b);
        out.vec(c);
        out.u16(0); // attribute byte count
    }
    files::writeFileAtomically(path, {out.bytes()});
}

void writePly(const std::filesystem::path& path, const SurfaceMesh& mesh) {
    checkWritable(path, mesh);
    const std::string header =
        "ply\n"
        "format binary_little_endian 1.0\n"
        "comment steerseg surface\n"
        "comment coordinates LPS mm: patient x left, y posterior, z superior (DICOM), "
        "millimetres\n"
        "element vertex " +
        std::to_string(mesh.vertices.size()) +
        "\n"
        "property float x\n"
        "property float y\n"
        "property float z\n"
        "element face " +
        std::to_string(mesh.triangles.size()) +
        "\n"
        "property list uchar int vertex_indices\n"
        "end_header\n";
    ByteWriter out;
    out.reserve(header.size() + 12 * mesh.vertices.size() + 13 * mesh.triangles.size());
    out.text(header);
    for (const auto& v : mesh.vertices) {
        out.vec(v);
    }
    for (const auto& t : mesh.triangles) {
        out.u8(3);
        for (std::uint32_t index : t) {
            out.u32(index);
        }
    }
    files::writeFileAtomically(path, {out.bytes()});
}

void writeMesh(const std::filesystem::path& path, const SurfaceMesh& mesh, MeshFormat format) {
    if (format == MeshFormat::Stl) {
        writeStl(path, mesh);
    } else {
        writePly(path, mesh);
    }
}

} // namespace steerseg::exports
