#include "core/mask_field.hpp"
#include "core/surface_mesh.hpp"
#include "exports/mesh_writer.hpp"
#include "scan/scan_reader.hpp"
#include "support/test_data.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace steerseg::test {
namespace {

Geometry grid(const glm::ivec3& dims, const glm::dvec3& spacing = glm::dvec3(1.0)) {
    Geometry g;
    g.dims = dims;
    g.spacing = spacing;
    return g;
}

// A rotated, left-handed grid away from the origin.
Geometry obliqueGrid(const glm::ivec3& dims) {
    Geometry g = grid(dims, {0.75, 1.25, 2.5});
    const double a = 0.5;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(1.0, 2.0, 3.0));
    glm::dmat3 r(std::cos(a));
    r += (1.0 - std::cos(a)) * glm::outerProduct(axis, axis);
    r += std::sin(a) * glm::dmat3(glm::dvec3(0, axis.z, -axis.y), glm::dvec3(-axis.z, 0, axis.x),
                                  glm::dvec3(axis.y, -axis.x, 0));
    r[1] = -r[1];
    g.direction = r;
    g.origin = {-112.5, 40.25, 307.0};
    return g;
}

// Signed distance in mm to a sphere of `radius` mm around `centre` (world), sampled at the
// voxel centres.
std::vector<float> sphereField(const Geometry& g, const glm::dvec3& centre, double radius) {
    std::vector<float> phi(g.voxelCount());
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                const glm::dvec3 w = g.indexToWorld(glm::dvec3(i, j, k));
                phi[linearIndex(g.dims, i, j, k)] =
                    static_cast<float>(glm::length(w - centre) - radius);
            }
        }
    }
    return phi;
}

double sphereVolume(double r) {
    return 4.0 / 3.0 * std::numbers::pi * r * r * r;
}

double maskVolume(const Geometry& g, const std::vector<float>& phi) {
    const auto inside = std::count_if(phi.begin(), phi.end(), [](float v) { return v < 0.0f; });
    return static_cast<double>(inside) * g.spacing.x * g.spacing.y * g.spacing.z;
}

// Closed and consistently oriented: every directed edge occurs once and its reverse once, so
// each edge joins exactly two triangles that wind it opposite ways. Returns the Euler
// characteristic V - E + F (2 for each sphere-like piece).
long checkWatertight(const SurfaceMesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    std::set<std::uint32_t> used;
    for (const auto& t : mesh.triangles) {
        for (int n = 0; n < 3; ++n) {
            const std::uint32_t a = t[static_cast<std::size_t>(n)];
            const std::uint32_t b = t[static_cast<std::size_t>((n + 1) % 3)];
            EXPECT_NE(a, b) << "a triangle repeats a vertex";
            EXPECT_LT(a, mesh.vertices.size());
            ++directed[{a, b}];
            used.insert(a);
        }
    }
    int bad = 0;
    for (const auto& [edge, count] : directed) {
        const auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1) {
            ++bad;
        }
    }
    EXPECT_EQ(bad, 0) << "edges not shared by exactly two oppositely wound triangles";
    EXPECT_EQ(used.size(), mesh.vertices.size()) << "vertices no triangle uses";
    return static_cast<long>(mesh.vertices.size()) - static_cast<long>(directed.size() / 2) +
           static_cast<long>(mesh.triangles.size());
}

struct SphereCase {
    glm::dvec3 spacing;
    double radiusMm;
};

class SphereSurface : public ::testing::TestWithParam<SphereCase> {};

TEST_P(SphereSurface, IsClosedOutwardAndOnTheSphere) {
    const Geometry g = grid({64, 64, 64}, GetParam().spacing);
    // Off the grid's symmetry, so no crossing falls on a voxel centre by construction.
    const glm::dvec3 centre = g.indexToWorld({31.3, 32.6, 30.8});
    const double r = GetParam().radiusMm;
    const auto phi = sphereField(g, centre, r);
    const SurfaceMesh mesh = extractSurface(g, phi);
    ASSERT_FALSE(mesh.empty());
    EXPECT_EQ(checkWatertight(mesh), 2);

    const double volume = enclosedVolume(mesh);
    const double analytic = sphereVolume(r);
    const double voxels = maskVolume(g, phi);
    const double errAnalytic = (volume - analytic) / analytic;
    const double errMask = (volume - voxels) / voxels;
    std::cout << "spacing " << g.spacing.x << "x" << g.spacing.y << "x" << g.spacing.z << ", r "
              << r << " mm: " << mesh.triangles.size() << " triangles, volume " << volume
              << " mm3, vs analytic " << 100.0 * errAnalytic << "%, vs voxel mask "
              << 100.0 * errMask << "%\n";
    EXPECT_GT(volume, 0.0) << "normals point inward";
    EXPECT_LT(std::abs(errAnalytic), 0.02);
    EXPECT_LT(std::abs(errMask), 0.02);

    const double minSpacing = std::min({g.spacing.x, g.spacing.y, g.spacing.z});
    double worst = 0.0;
    for (const auto& v : mesh.vertices) {
        worst = std::max(worst, std::abs(glm::length(v - centre) - r));
    }
    std::cout << "  farthest vertex from the sphere: " << worst / minSpacing << " voxel\n";
    EXPECT_LT(worst, 0.1 * minSpacing);

    // Each facet faces away from the centre.
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a = mesh.vertices[t[0]];
        const glm::dvec3 n = glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
        if (glm::length(n) > 1e-9) {
            ASSERT_GT(glm::dot(n, a - centre), 0.0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Spacings, SphereSurface,
                         ::testing::Values(SphereCase{{1.0, 1.0, 1.0}, 20.0},
                                           SphereCase{{0.9, 1.0, 1.3}, 20.0},
                                           SphereCase{{0.5, 0.5, 1.0}, 12.0}),
                         [](const ::testing::TestParamInfo<SphereCase>& p) {
                             const glm::dvec3 s = p.param.spacing;
                             return s.x == s.y && s.y == s.z
                                        ? std::string("isotropic")
                                        : "anisotropic" + std::to_string(p.index);
                         });

// A region cut by the grid's edge still gives a closed surface: it closes on the outer face
// of the last voxels.
TEST(SurfaceMesh, RegionTouchingTheBorderIsClosed) {
    const Geometry g = grid({40, 36, 30});
    const auto phi = sphereField(g, {0.0, 17.5, 29.0}, 12.0); // through three faces
    const SurfaceMesh mesh = extractSurface(g, phi);
    EXPECT_EQ(checkWatertight(mesh), 2);
    EXPECT_GT(enclosedVolume(mesh), 0.0);
    double minX = 1e9;
    for (const auto& v : mesh.vertices) {
        minX = std::min(minX, v.x);
    }
    EXPECT_DOUBLE_EQ(minX, -0.5) << "the cut face sits on the first voxels' outer face";

    // Everything inside: a closed box around the whole grid.
    const Geometry small = grid({5, 4, 3});
    const SurfaceMesh full = extractSurface(small, std::vector<float>(small.voxelCount(), -1.0f));
    EXPECT_EQ(checkWatertight(full), 2);
    EXPECT_GT(enclosedVolume(full), 0.0);
    EXPECT_LE(enclosedVolume(full), 5.0 * 4.0 * 3.0);
}

TEST(SurfaceMesh, MaskFieldFollowsTheMask) {
    const Geometry g = grid({64, 64, 64}, {0.9, 1.0, 1.3});
    const glm::dvec3 centre = g.indexToWorld({31.3, 32.6, 30.8});
    const auto phi = sphereField(g, centre, 20.0);
    std::vector<std::uint8_t> mask(phi.size());
    std::transform(phi.begin(), phi.end(), mask.begin(), [](float v) { return v < 0.0f ? 1 : 0; });
    const SurfaceMesh mesh = extractSurface(g, maskToField(g, mask));
    EXPECT_EQ(checkWatertight(mesh), 2);
    const double volume = enclosedVolume(mesh);
    const double voxels = maskVolume(g, phi);
    std::cout << "mask field: volume vs voxel mask " << 100.0 * (volume - voxels) / voxels << "%\n";
    EXPECT_LT(std::abs(volume - voxels) / voxels, 0.02);
}

TEST(SurfaceMesh, EmptyFieldGivesNoMeshAndNoFile) {
    const Geometry g = grid({8, 8, 8});
    const SurfaceMesh mesh = extractSurface(g, std::vector<float>(g.voxelCount(), 1.0f));
    EXPECT_TRUE(mesh.empty());
    EXPECT_TRUE(mesh.vertices.empty());
    EXPECT_EQ(enclosedVolume(mesh), 0.0);
    const auto dir = tempDir("mesh-empty");
    for (const char* name : {"empty.stl", "empty.ply"}) {
        EXPECT_THROW(exports::writeMesh(dir / name, mesh, *exports::meshFormatFor(name)),
                     files::WriteError);
        EXPECT_FALSE(std::filesystem::exists(dir / name));
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir)) << "a temporary file was left behind";
}

TEST(SurfaceMesh, RejectsAFieldOfTheWrongSize) {
    EXPECT_THROW(extractSurface(grid({4, 4, 4}), std::vector<float>(63, -1.0f)),
                 std::invalid_argument);
}

// The vertices land where the scan's geometry puts those fractional indices, in LPS, and a
// left-handed grid still gives outward normals.
TEST(SurfaceMesh, VerticesAreInTheScansPatientCoordinates) {
    const glm::ivec3 dims(30, 26, 22);
    const Geometry oblique = obliqueGrid(dims);
    ASSERT_LT(glm::determinant(oblique.direction), 0.0);
    const Geometry plain = grid(dims);
    // The same field on both grids: a sphere in index space.
    const auto phi = sphereField(plain, {14.2, 12.7, 10.4}, 8.0);
    const SurfaceMesh inIndex = extractSurface(plain, phi);
    const SurfaceMesh inWorld = extractSurface(oblique, phi);
    ASSERT_EQ(inIndex.vertices.size(), inWorld.vertices.size());
    ASSERT_EQ(inIndex.triangles.size(), inWorld.triangles.size());
    for (std::size_t n = 0; n < inIndex.vertices.size(); ++n) {
        const glm::dvec3 expected = oblique.indexToWorld(inIndex.vertices[n]);
        ASSERT_NEAR(glm::distance(inWorld.vertices[n], expected), 0.0, 1e-9) << n;
    }
    EXPECT_EQ(checkWatertight(inWorld), 2);
    const double scale = oblique.spacing.x * oblique.spacing.y * oblique.spacing.z;
    EXPECT_NEAR(enclosedVolume(inWorld), enclosedVolume(inIndex) * scale,
                1e-6 * enclosedVolume(inWorld));
    EXPECT_GT(enclosedVolume(inWorld), 0.0);
}

// Independent little readers for the two formats.
std::string readAll(const std::filesystem::path& path) {
    std::string bytes(std::filesystem::file_size(path), '\0');
    std::ifstream in(path, std::ios::binary);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(in.good()) << path;
    return bytes;
}

template <typename T> T at(const std::string& bytes, std::size_t offset) {
    T v{};
    EXPECT_LE(offset + sizeof(T), bytes.size());
    if (offset + sizeof(T) <= bytes.size()) {
        std::memcpy(&v, bytes.data() + offset, sizeof(T)); // the test host is little-endian
    }
    return v;
}

glm::dvec3 vecAt(const std::string& bytes, std::size_t offset) {
    return {at<float>(bytes, offset), at<float>(bytes, offset + 4), at<float>(bytes, offset + 8)};
}

TEST(MeshWriter, StlAndPlyReadBack) {
    static_assert(std::endian::native == std::endian::little);
    const Geometry g = obliqueGrid({30, 26, 22});
    const glm::dvec3 centre = g.indexToWorld({14.2, 12.7, 10.4});
    const SurfaceMesh mesh = extractSurface(g, sphereField(g, centre, 9.0));
    ASSERT_FALSE(mesh.empty());
    const auto dir = tempDir("mesh-roundtrip");
    const double tolerance = 1e-4; // float32 of coordinates a few hundred mm from the origin

    exports::writeMesh(dir / "s.STL", mesh, *exports::meshFormatFor("s.STL"));
    const std::string stl = readAll(dir / "s.STL");
    ASSERT_EQ(stl.size(), 84 + 50 * mesh.triangles.size());
    EXPECT_EQ(stl.rfind("steerseg surface, LPS mm", 0), 0u);
    EXPECT_EQ(at<std::uint32_t>(stl, 80), mesh.triangles.size());
    for (std::size_t n = 0; n < mesh.triangles.size(); n += 97) {
        const std::size_t facet = 84 + 50 * n;
        const glm::dvec3 normal = vecAt(stl, facet);
        for (int c = 0; c < 3; ++c) {
            const glm::dvec3 v = vecAt(stl, facet + 12 + 12 * static_cast<std::size_t>(c));
            EXPECT_NEAR(
                glm::distance(v, mesh.vertices[mesh.triangles[n][static_cast<std::size_t>(c)]]),
                0.0, tolerance);
        }
        EXPECT_NEAR(glm::length(normal), 1.0, 1e-5);
        EXPECT_GT(glm::dot(normal, vecAt(stl, facet + 12) - centre), 0.0) << "facet " << n;
    }

    exports::writeMesh(dir / "s.ply", mesh, exports::MeshFormat::Ply);
    const std::string ply = readAll(dir / "s.ply");
    const std::size_t end = ply.find("end_header\n");
    ASSERT_NE(end, std::string::npos);
    const std::string header = ply.substr(0, end);
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u);
    EXPECT_NE(header.find("comment coordinates LPS mm"), std::string::npos);
    std::istringstream lines(header);
    std::string line;
    std::size_t vertexCount = 0;
    std::size_t faceCount = 0;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string word;
        std::string element;
        std::size_t count = 0;
        if (words >> word >> element >> count && word == "element") {
            (element == "vertex" ? vertexCount : faceCount) = count;
        }
    }
    ASSERT_EQ(vertexCount, mesh.vertices.size());
    ASSERT_EQ(faceCount, mesh.triangles.size());
    const std::size_t body = end + std::strlen("end_header\n");
    ASSERT_EQ(ply.size(), body + 12 * vertexCount + 13 * faceCount);
    for (std::size_t n = 0; n < vertexCount; n += 53) {
        EXPECT_NEAR(glm::distance(vecAt(ply, body + 12 * n), mesh.vertices[n]), 0.0, tolerance);
    }
    const std::size_t faces = body + 12 * vertexCount;
    for (std::size_t n = 0; n < faceCount; n += 89) {
        EXPECT_EQ(at<std::uint8_t>(ply, faces + 13 * n), 3);
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(at<std::uint32_t>(ply, faces + 13 * n + 1 + 4 * c), mesh.triangles[n][c]);
        }
    }
    std::set<std::filesystem::path> left;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        left.insert(e.path().filename());
    }
    EXPECT_EQ(left, (std::set<std::filesystem::path>{"s.STL", "s.ply"}));
}

TEST(MeshWriter, FormatByExtensionAndClearFailures) {
    EXPECT_EQ(exports::meshFormatFor("a/b.Stl"), exports::MeshFormat::Stl);
    EXPECT_EQ(exports::meshFormatFor("b.ply"), exports::MeshFormat::Ply);
    EXPECT_FALSE(exports::meshFormatFor("b.nii.gz").has_value());
    EXPECT_FALSE(exports::meshFormatFor("stl").has_value());

    const Geometry g = grid({8, 8, 8});
    const SurfaceMesh mesh = extractSurface(g, sphereField(g, {3.5, 3.5, 3.5}, 2.5));
    const auto missing = tempDir("mesh-fail") / "no-such-folder" / "s.stl";
    try {
        exports::writeStl(missing, mesh);
        FAIL() << "wrote into a missing folder";
    } catch (const files::WriteError& e) {
        EXPECT_NE(std::string(e.what()).find("s.stl"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace steerseg::test
