// Marching tetrahedra over the voxel-centre grid, padded with "outside" all round.
#include "core/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace steerseg {

namespace {

// Cube corner c sits at offset (c & 1, c >> 1 & 1, c >> 2 & 1). The six tetrahedra of the
// Kuhn decomposition each follow the main diagonal 0 -> 7 through one axis order; any two of
// their corners are ordered componentwise, so every edge runs from a corner `lo` to a corner
// `hi` that holds lo's bits and more, and an edge is named by (lo's grid point, hi ^ lo).
constexpr std::array<std::array<int, 4>, 6> kTets{{
    {0, 1, 3, 7},
    {0, 1, 5, 7},
    {0, 2, 3, 7},
    {0, 2, 6, 7},
    {0, 4, 5, 7},
    {0, 4, 6, 7},
}};

struct Edge {
    int lo = 0;
    int hi = 0;
};
using Triangle = std::array<Edge, 3>;

// The triangles one tetrahedron contributes for one pattern of inside corners (bit n for its
// corner n), at most two.
struct TetCase {
    int count = 0;
    std::array<Triangle, 2> triangles{};
};
using CaseTable = std::array<std::array<TetCase, 16>, 6>;

glm::dvec3 cornerOffset(int c) {
    return {static_cast<double>(c & 1), static_cast<double>((c >> 1) & 1),
            static_cast<double>((c >> 2) & 1)};
}

Edge edgeBetween(int a, int b) {
    return (a & b) == a ? Edge{a, b} : Edge{b, a};
}

glm::dvec3 midpoint(const Edge& e) {
    return 0.5 * (cornerOffset(e.lo) + cornerOffset(e.hi));
}

// The winding is decided once per case on the field that is -1 at the inside corners and +1
// at the others, whose crossings are the edge midpoints: there the polygon is planar and never
// degenerate, and its outward side is the one facing the outside corners. Any field with the
// same signs gives the same combinatorial surface, so the same winding holds for all of them,
// and neighbouring tetrahedra agree on their shared faces.
TetCase buildCase(const std::array<int, 4>& tet, int pattern) {
    std::array<int, 4> in{};
    std::array<int, 4> out{};
    std::size_t nIn = 0;
    std::size_t nOut = 0;
    for (std::size_t n = 0; n < 4; ++n) {
        if ((pattern >> n) & 1) {
            in[nIn++] = tet[n];
        } else {
            out[nOut++] = tet[n];
        }
    }
    TetCase result;
    if (nIn == 0 || nOut == 0) {
        return result;
    }
    glm::dvec3 inCentre(0.0);
    glm::dvec3 outCentre(0.0);
    for (std::size_t n = 0; n < nIn; ++n) {
        inCentre += cornerOffset(in[n]) / static_cast<double>(nIn);
    }
    for (std::size_t n = 0; n < nOut; ++n) {
        outCentre += cornerOffset(out[n]) / static_cast<double>(nOut);
    }
    const glm::dvec3 outward = outCentre - inCentre;

    std::array<Edge, 4> polygon{};
    std::size_t sides = 0;
    if (nIn == 1 || nOut == 1) {
        const bool lonelyInside = nIn == 1;
        const int apex = lonelyInside ? in[0] : out[0];
        const auto& others = lonelyInside ? out : in;
        for (std::size_t n = 0; n < 3; ++n) {
            polygon[sides++] = edgeBetween(apex, others[n]);
        }
    } else {
        // Around the quad: in0-out0, in0-out1, in1-out1, in1-out0.
        polygon = {edgeBetween(in[0], out[0]), edgeBetween(in[0], out[1]),
                   edgeBetween(in[1], out[1]), edgeBetween(in[1], out[0])};
        sides = 4;
    }
    const glm::dvec3 a = midpoint(polygon[0]);
    const glm::dvec3 normal = glm::cross(midpoint(polygon[1]) - a, midpoint(polygon[2]) - a);
    if (glm::dot(normal, outward) < 0.0) {
        std::swap(polygon[1], polygon[sides - 1]); // the same cycle, run the other way
    }
    result.triangles[0] = {polygon[0], polygon[1], polygon[2]};
    result.count = 1;
    if (sides == 4) {
        result.triangles[1] = {polygon[0], polygon[2], polygon[3]};
        result.count = 2;
    }
    return result;
}

const CaseTable& caseTable() {
    static const CaseTable table = [] {
        CaseTable t{};
        for (std::size_t tet = 0; tet < kTets.size(); ++tet) {
            for (int pattern = 0; pattern < 16; ++pattern) {
                t[tet][static_cast<std::size_t>(pattern)] = buildCase(kTets[tet], pattern);
            }
        }
        return t;
    }();
    return table;
}

// One grid point of the padded grid: a voxel's phi, or "outside" beyond the grid.
struct Sample {
    float phi = 0.0f;
    bool real = false; // a finite value from the field, not padding or NaN
    bool inside = false;
};

class Extractor {
  public:
    Extractor(const Geometry& geometry, std::span<const float> phi)
        : geometry_(geometry), dims_(geometry.dims), phi_(phi) {
        // A left-handed grid (a flipped axis) mirrors the mesh, which turns its winding over.
        flip_ = glm::determinant(geometry.direction) * geometry.spacing.x * geometry.spacing.y *
                    geometry.spacing.z <
                0.0;
    }

    SurfaceMesh run() {
        const CaseTable& table = caseTable();
        std::array<Sample, 8> corner{};
        for (int k = -1; k < dims_.z; ++k) {
            for (int j = -1; j < dims_.y; ++j) {
                // The four rows of voxels along i that this row of cubes spans (y, z offsets as
                // in the corner numbering), null where they lie in the padding. Most cubes are
                // all inside or all outside; their signs are read once per voxel, sliding along
                // i, and only the cubes the surface crosses fetch their corners.
                std::array<const float*, 4> rows{};
                for (std::size_t r = 0; r < 4; ++r) {
                    const int y = j + static_cast<int>(r & 1);
                    const int z = k + static_cast<int>(r >> 1);
                    rows[r] = y >= 0 && z >= 0 && y < dims_.y && z < dims_.z
                                  ? phi_.data() + linearIndex(dims_, 0, y, z)
                                  : nullptr;
                }
                if (rows[0] == nullptr && rows[1] == nullptr && rows[2] == nullptr &&
                    rows[3] == nullptr) {
                    continue;
                }
                // Bit 2r set when row r is inside at column i: cube corner 2r (x = 0); shifted
                // by one it is corner 2r + 1 (x = 1).
                const auto column = [&](int i) {
                    int bits = 0;
                    if (i >= 0 && i < dims_.x) {
                        for (std::size_t r = 0; r < 4; ++r) {
                            bits |= rows[r] != nullptr && rows[r][i] < 0.0f ? 1 << (2 * r) : 0;
                        }
                    }
                    return bits;
                };
                int left = column(-1);
                for (int i = -1; i < dims_.x; ++i) {
                    const int right = column(i + 1);
                    const int insideBits = left | (right << 1);
                    left = right;
                    if (insideBits == 0 || insideBits == 0xff) {
                        continue;
                    }
                    for (int c = 0; c < 8; ++c) {
                        corner[static_cast<std::size_t>(c)] =
                            sample(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
                    }
                    const glm::ivec3 base(i, j, k);
                    for (std::size_t t = 0; t < kTets.size(); ++t) {
                        int pattern = 0;
                        for (int n = 0; n < 4; ++n) {
                            pattern |= ((insideBits >> kTets[t][static_cast<std::size_t>(n)]) & 1)
                                       << n;
                        }
                        const TetCase& tc = table[t][static_cast<std::size_t>(pattern)];
                        for (int n = 0; n < tc.count; ++n) {
                            emit(base, corner, tc.triangles[static_cast<std::size_t>(n)]);
                        }
                    }
                }
            }
        }
        return std::move(mesh_);
    }

  private:
    Sample sample(int i, int j, int k) const {
        if (i < 0 || j < 0 || k < 0 || i >= dims_.x || j >= dims_.y || k >= dims_.z) {
            return {};
        }
        const float v = phi_[linearIndex(dims_, i, j, k)];
        return {v, std::isfinite(v), v < 0.0f};
    }

    // Grid points of the padded grid, which starts at -1 on every axis.
    std::uint64_t paddedIndex(const glm::ivec3& p) const {
        const auto nx = static_cast<std::uint64_t>(dims_.x) + 2;
        const auto ny = static_cast<std::uint64_t>(dims_.y) + 2;
        return static_cast<std::uint64_t>(p.x + 1) +
               nx *
                   (static_cast<std::uint64_t>(p.y + 1) + ny * static_cast<std::uint64_t>(p.z + 1));
    }

    std::uint32_t vertexOn(const glm::ivec3& base, const std::array<Sample, 8>& corner,
                           const Edge& e) {
        const glm::ivec3 lo = base + glm::ivec3(e.lo & 1, (e.lo >> 1) & 1, (e.lo >> 2) & 1);
        const std::uint64_t key = paddedIndex(lo) * 8 + static_cast<std::uint64_t>(e.hi ^ e.lo);
        const auto [it, added] =
            vertexOfEdge_.try_emplace(key, static_cast<std::uint32_t>(mesh_.vertices.size()));
        if (!added) {
            return it->second;
        }
        const Sample& a = corner[static_cast<std::size_t>(e.lo)];
        const Sample& b = corner[static_cast<std::size_t>(e.hi)];
        // Towards padding (or a NaN) there is no second value to interpolate with: the
        // boundary goes halfway, on the last voxel's outer face.
        double t = 0.5;
        if (a.real && b.real) {
            t = static_cast<double>(a.phi) /
                (static_cast<double>(a.phi) - static_cast<double>(b.phi));
            t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.5;
        }
        const glm::dvec3 index = glm::dvec3(lo) + t * (cornerOffset(e.hi) - cornerOffset(e.lo));
        mesh_.vertices.push_back(geometry_.indexToWorld(index));
        return it->second;
    }

    void emit(const glm::ivec3& base, const std::array<Sample, 8>& corner, const Triangle& tri) {
        std::array<std::uint32_t, 3> v{vertexOn(base, corner, tri[0]),
                                       vertexOn(base, corner, tri[1]),
                                       vertexOn(base, corner, tri[2])};
        if (flip_) {
            std::swap(v[1], v[2]);
        }
        mesh_.triangles.push_back(v);
    }

    const Geometry& geometry_;
    glm::ivec3 dims_;
    std::span<const float> phi_;
    bool flip_ = false;
    SurfaceMesh mesh_;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexOfEdge_;
};

} // namespace

SurfaceMesh extractSurface(const Geometry& geometry, std::span<const float> phi) {
    if (geometry.dims.x <= 0 || geometry.dims.y <= 0 || geometry.dims.z <= 0) {
        throw std::invalid_argument("surface extraction needs a grid of at least one voxel");
    }
    if (phi.size() != geometry.voxelCount()) {
        throw std::invalid_argument("the level set has " + std::to_string(phi.size()) +
                                    " values for a grid of " +
                                    std::to_string(geometry.voxelCount()) + " voxels");
    }
    return Extractor(geometry, phi).run();
}

double surfaceArea(const SurfaceMesh& mesh) {
    double sum = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3& a = mesh.vertices[t[0]];
        sum += glm::length(glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a));
    }
    return 0.5 * sum;
}

double enclosedVolume(const SurfaceMesh& mesh) {
    if (mesh.vertices.empty()) {
        return 0.0;
    }
    // Relative to a vertex of the mesh: patient coordinates can sit far from the origin, and
    // the sum of large signed terms would lose the small difference that is the volume.
    const glm::dvec3 ref = mesh.vertices.front();
    double sum = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 a = mesh.vertices[t[0]] - ref;
        const glm::dvec3 b = mesh.vertices[t[1]] - ref;
        const glm::dvec3 c = mesh.vertices[t[2]] - ref;
        sum += glm::dot(a, glm::cross(b, c));
    }
    return sum / 6.0;
}

} // namespace steerseg
