// Known answers for core/mask_measurements on anisotropic grids: digitised spheres, ellipsoids
// and boxes against their analytic sizes, the diameters against all pairs of voxel centres,
// the intensity figures exactly, and the axial slices of a sagittal-acquired scan.
#include "core/mask_field.hpp"
#include "core/mask_measurements.hpp"
#include "core/surface_mesh.hpp"
#include "render/slice_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace steerseg::test {
namespace {

const glm::dvec3 kSpacing{0.7, 0.9, 2.5};

Volume scanOn(const glm::ivec3& dims, const glm::dvec3& spacing = kSpacing) {
    Geometry g;
    g.dims = dims;
    g.spacing = spacing;
    g.origin = {-120.0, 35.5, 210.0};
    return Volume(VoxelType::Int16, g);
}

// 1 where `inside` holds at the voxel centre's place in millimetres from voxel (0, 0, 0).
std::vector<std::uint8_t> maskWhere(const Geometry& g,
                                    const std::function<bool(const glm::dvec3&)>& inside) {
    std::vector<std::uint8_t> mask(g.voxelCount());
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                mask[linearIndex(g.dims, i, j, k)] =
                    inside(glm::dvec3(i, j, k) * g.spacing) ? 1 : 0;
            }
        }
    }
    return mask;
}

std::uint64_t countInside(const std::vector<std::uint8_t>& mask) {
    return static_cast<std::uint64_t>(std::count(mask.begin(), mask.end(), std::uint8_t{1}));
}

double voxelMl(const Geometry& g) {
    return g.spacing.x * g.spacing.y * g.spacing.z / 1000.0;
}

// An ellipsoid's area by the midpoint rule over its parameters, to a few parts in a million.
double ellipsoidArea(const glm::dvec3& r) {
    const int n = 1200;
    double sum = 0.0;
    for (int t = 0; t < n; ++t) {
        const double theta = std::numbers::pi * (t + 0.5) / n;
        for (int p = 0; p < 2 * n; ++p) {
            const double phi = std::numbers::pi * (p + 0.5) / n;
            const glm::dvec3 dTheta(r.x * std::cos(theta) * std::cos(phi),
                                    r.y * std::cos(theta) * std::sin(phi), -r.z * std::sin(theta));
            const glm::dvec3 dPhi(-r.x * std::sin(theta) * std::sin(phi),
                                  r.y * std::sin(theta) * std::cos(phi), 0.0);
            sum += glm::length(glm::cross(dTheta, dPhi));
        }
    }
    return sum * (std::numbers::pi / n) * (std::numbers::pi / n);
}

// The segments' ends lie on the measured slice, their lengths are the world distances between
// them, and the perpendicular is at right angles to the longest.
void expectConsistentLines(const Geometry& g, const MaskMeasurements& m) {
    const int s = m.axial.sliceAxis;
    for (const MeasuredLine* line : {&m.axial.longest, &m.axial.perpendicular, &m.longest3d}) {
        EXPECT_NEAR(line->lengthMm, glm::distance(line->world[0], line->world[1]), 1e-9);
        for (int e = 0; e < 2; ++e) {
            EXPECT_NEAR(glm::distance(g.indexToWorld(line->index[e]), line->world[e]), 0.0, 1e-9);
        }
    }
    for (const MeasuredLine* line : {&m.axial.longest, &m.axial.perpendicular}) {
        EXPECT_EQ(line->index[0][s], m.axial.slice);
        EXPECT_EQ(line->index[1][s], m.axial.slice);
    }
    const glm::dvec3 a = m.axial.longest.world[1] - m.axial.longest.world[0];
    const glm::dvec3 b = m.axial.perpendicular.world[1] - m.axial.perpendicular.world[0];
    EXPECT_NEAR(glm::dot(a, b), 0.0, 1e-9 * glm::length(a) * std::max(1.0, glm::length(b)));
    EXPECT_LE(m.axial.perpendicular.lengthMm, m.axial.longest.lengthMm + 1e-9);
    EXPECT_LE(m.axial.longest.lengthMm, m.longest3d.lengthMm + 1e-9);
}

TEST(MaskMeasurements, SphereOnAnAnisotropicGrid) {
    const Volume scan = scanOn({60, 48, 20});
    const Geometry& g = scan.geometry();
    const glm::dvec3 centre(20.83, 21.37, 24.61);
    const double r = 15.0;
    const auto mask =
        maskWhere(g, [&](const glm::dvec3& p) { return glm::distance(p, centre) <= r; });
    const MaskMeasurements m = measureMask(scan, mask);

    EXPECT_EQ(m.voxels, countInside(mask));
    EXPECT_DOUBLE_EQ(m.volumeMl, static_cast<double>(m.voxels) * voxelMl(g));
    EXPECT_NEAR(m.volumeMl, 4.0 / 3.0 * std::numbers::pi * r * r * r / 1000.0, 0.02 * m.volumeMl);
    const double area = 4.0 * std::numbers::pi * r * r;
    EXPECT_NEAR(m.surfaceAreaMm2, area, 0.02 * area);
    // Between voxel centres: short of the true diameter by at most a voxel's diagonal in the
    // plane (the centres nearest the rim lie inside it), never beyond it.
    const double inPlane = std::hypot(kSpacing.x, kSpacing.y);
    EXPECT_EQ(m.axial.sliceAxis, 2);
    EXPECT_LE(m.axial.longest.lengthMm, 2.0 * r);
    EXPECT_GE(m.axial.longest.lengthMm, 2.0 * r - inPlane);
    EXPECT_GE(m.axial.perpendicular.lengthMm, 2.0 * r - 2.0 * inPlane);
    EXPECT_LE(m.longest3d.lengthMm, 2.0 * r);
    EXPECT_GE(m.longest3d.lengthMm, 2.0 * r - inPlane);
    expectConsistentLines(g, m);
}

TEST(MaskMeasurements, EllipsoidLongestAxisAlongTheSlices) {
    const Volume scan = scanOn({70, 40, 26});
    const Geometry& g = scan.geometry();
    const glm::dvec3 centre(24.13, 17.71, 32.2);
    const glm::dvec3 radii(20.0, 12.0, 26.0); // x, y in the axial plane; z across the slices
    const auto mask = maskWhere(g, [&](const glm::dvec3& p) {
        const glm::dvec3 u = (p - centre) / radii;
        return glm::dot(u, u) <= 1.0;
    });
    const MaskMeasurements m = measureMask(scan, mask);

    EXPECT_NEAR(m.volumeMl, 4.0 / 3.0 * std::numbers::pi * radii.x * radii.y * radii.z / 1000.0,
                0.02 * m.volumeMl);
    const double area = ellipsoidArea(radii);
    EXPECT_NEAR(m.surfaceAreaMm2, area, 0.02 * area);
    const double inPlane = std::hypot(kSpacing.x, kSpacing.y);
    EXPECT_GE(m.axial.longest.lengthMm, 2.0 * radii.x - inPlane);
    EXPECT_LE(m.axial.longest.lengthMm, 2.0 * radii.x);
    EXPECT_GE(m.axial.perpendicular.lengthMm, 2.0 * radii.y - 2.0 * inPlane);
    EXPECT_LE(m.axial.perpendicular.lengthMm, 2.0 * radii.y);
    // The long axis runs along x on a slice near the centre.
    const glm::dvec3 along = m.axial.longest.world[1] - m.axial.longest.world[0];
    EXPECT_GT(std::abs(along.x), 0.99 * glm::length(along));
    EXPECT_NEAR(m.axial.slice * kSpacing.z, centre.z, kSpacing.z);
    // The longest 3D diameter runs across the slices (z), where the grid is coarsest.
    EXPECT_LE(m.longest3d.lengthMm, 2.0 * radii.z);
    EXPECT_GE(m.longest3d.lengthMm, 2.0 * radii.z - kSpacing.z);
    expectConsistentLines(g, m);
}

// A box of whole voxels: its volume is exact, its faces lie on the voxels' outer faces, and its
// diameters are known exactly between the corner voxels' centres. On each slice the longest
// is the rectangle's diagonal; at right angles to it the longest chord runs from a corner to
// the far long side: the short side times diagonal / long side. Its edges round off inside
// their voxels, about 1 mm^2 per mm of edge on this grid (docs/measurements.md), so its area is
// within 2 % from some 12 cm across.
TEST(MaskMeasurements, BoxOfWholeVoxels) {
    const Volume scan = scanOn({236, 158, 66});
    const Geometry& g = scan.geometry();
    const glm::ivec3 lo(5, 3, 2);
    const glm::ivec3 n(228, 150, 60); // 159.6 x 135 x 150 mm of voxels
    std::vector<std::uint8_t> mask(g.voxelCount());
    for (int k = lo.z; k < lo.z + n.z; ++k) {
        for (int j = lo.y; j < lo.y + n.y; ++j) {
            for (int i = lo.x; i < lo.x + n.x; ++i) {
                mask[linearIndex(g.dims, i, j, k)] = 1;
            }
        }
    }
    const MaskMeasurements m = measureMask(scan, mask);

    EXPECT_EQ(m.voxels, static_cast<std::uint64_t>(n.x) * n.y * n.z);
    const glm::dvec3 extent = glm::dvec3(n) * kSpacing;
    EXPECT_NEAR(m.volumeMl, extent.x * extent.y * extent.z / 1000.0, 1e-9);
    const double area = 2.0 * (extent.x * extent.y + extent.x * extent.z + extent.y * extent.z);
    EXPECT_NEAR(m.surfaceAreaMm2, area, 0.02 * area);
    EXPECT_LT(m.surfaceAreaMm2, area); // its edges round off, inside the voxels

    const glm::dvec3 centres = glm::dvec3(n - 1) * kSpacing;
    const double diagonal = std::hypot(centres.x, centres.y);
    EXPECT_NEAR(m.axial.longest.lengthMm, diagonal, 1e-9);
    EXPECT_NEAR(m.axial.perpendicular.lengthMm, centres.y * diagonal / centres.x, 1e-9);
    EXPECT_EQ(m.axial.slice, lo.z); // every slice is the same: the lowest
    EXPECT_NEAR(m.longest3d.lengthMm, glm::length(centres), 1e-9);
    expectConsistentLines(g, m);
}

// The diameters are exact over voxel centres: the same as comparing every pair of them.
TEST(MaskMeasurements, DiametersEqualAllPairsOfVoxelCentres) {
    Volume scan = scanOn({24, 22, 9});
    Geometry& g = scan.geometry();
    const double a = 0.4; // an oblique grid: the distances go through its direction
    g.direction = glm::dmat3(glm::dvec3(std::cos(a), std::sin(a), 0.0),
                             glm::dvec3(-std::sin(a), std::cos(a), 0.0), glm::dvec3(0, 0, 1));
    // An irregular blob: two overlapping ellipsoids and a stray voxel.
    auto mask = maskWhere(g, [](const glm::dvec3& p) {
        const glm::dvec3 u = (p - glm::dvec3(7.0, 9.0, 9.0)) / glm::dvec3(5.0, 4.0, 8.0);
        const glm::dvec3 v = (p - glm::dvec3(10.5, 11.0, 12.0)) / glm::dvec3(4.0, 7.0, 5.0);
        return glm::dot(u, u) <= 1.0 || glm::dot(v, v) <= 1.0;
    });
    mask[linearIndex(g.dims, 20, 3, 6)] = 1;
    const MaskMeasurements m = measureMask(scan, mask);

    std::vector<glm::ivec3> inside;
    for (int k = 0; k < g.dims.z; ++k) {
        for (int j = 0; j < g.dims.y; ++j) {
            for (int i = 0; i < g.dims.x; ++i) {
                if (mask[linearIndex(g.dims, i, j, k)] != 0) {
                    inside.emplace_back(i, j, k);
                }
            }
        }
    }
    double longest3d = 0.0;
    double longestAxial = 0.0;
    for (std::size_t p = 0; p < inside.size(); ++p) {
        for (std::size_t q = p + 1; q < inside.size(); ++q) {
            const double d = glm::distance(g.indexToWorld(glm::dvec3(inside[p])),
                                           g.indexToWorld(glm::dvec3(inside[q])));
            longest3d = std::max(longest3d, d);
            if (inside[p].z == inside[q].z) {
                longestAxial = std::max(longestAxial, d);
            }
        }
    }
    EXPECT_NEAR(m.longest3d.lengthMm, longest3d, 1e-9);
    EXPECT_NEAR(m.axial.longest.lengthMm, longestAxial, 1e-9);
    expectConsistentLines(g, m);
}

// The scan's real values (rescaled, as HU are) over the mask, exactly; population sd.
TEST(MaskMeasurements, IntensityOverTheMaskInRealUnits) {
    Volume scan = scanOn({4, 3, 2}, {1.0, 1.0, 1.0});
    scan.setRescale({2.0, -1024.0});
    auto stored = scan.voxels<std::int16_t>();
    for (std::size_t n = 0; n < stored.size(); ++n) {
        stored[n] = static_cast<std::int16_t>(500 + n); // outside values, never counted
    }
    std::vector<std::uint8_t> mask(stored.size());
    const std::array<std::int16_t, 4> values{10, 20, 30, 40};
    const std::array<std::size_t, 4> at{1, 6, 13, 22};
    for (std::size_t n = 0; n < at.size(); ++n) {
        stored[at[n]] = values[n];
        mask[at[n]] = 1;
    }
    scan.invalidateStats();
    const MaskMeasurements m = measureMask(scan, mask);
    EXPECT_EQ(m.voxels, 4u);
    EXPECT_DOUBLE_EQ(m.intensity.mean, 2.0 * 25.0 - 1024.0);
    EXPECT_DOUBLE_EQ(m.intensity.sd, 2.0 * std::sqrt(125.0));
    EXPECT_DOUBLE_EQ(m.intensity.min, 2.0 * 10.0 - 1024.0);
    EXPECT_DOUBLE_EQ(m.intensity.max, 2.0 * 40.0 - 1024.0);
}

// A sagittal acquisition: i runs A->P, j S->I, k R->L. The axial slices are j = const, as the
// axial view (render::sliceAxisFor) shows them.
TEST(MaskMeasurements, AxialSlicesOfASagittalScanAreTheViewsOnes) {
    Volume scan = scanOn({40, 30, 36}, {0.8, 0.8, 2.0});
    Geometry& g = scan.geometry();
    g.direction = glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0));
    EXPECT_EQ(axialSliceAxis(g), render::sliceAxisFor(g, render::ViewKind::Axial));
    EXPECT_EQ(axialSliceAxis(g), 1);
    // A slab thin along j (superior-inferior), long along k (left-right): its longest axial
    // diameter lies within one j slice and runs along k.
    std::vector<std::uint8_t> mask(g.voxelCount());
    for (int k = 4; k < 32; ++k) {
        for (int j = 12; j < 15; ++j) {
            for (int i = 10; i < 20; ++i) {
                mask[linearIndex(g.dims, i, j, k)] = 1;
            }
        }
    }
    const MaskMeasurements m = measureMask(scan, mask);
    EXPECT_EQ(m.axial.sliceAxis, 1);
    EXPECT_EQ(m.axial.slice, 12);
    EXPECT_NEAR(m.axial.longest.lengthMm, std::hypot(27 * 2.0, 9 * 0.8), 1e-9);
    expectConsistentLines(g, m);

    for (const glm::dmat3& oblique :
         {glm::dmat3(glm::dvec3(0.8, 0.6, 0), glm::dvec3(0, 0, 1), glm::dvec3(0.6, -0.8, 0)),
          glm::dmat3(1.0)}) {
        g.direction = oblique;
        EXPECT_EQ(axialSliceAxis(g), render::sliceAxisFor(g, render::ViewKind::Axial));
    }
}

TEST(MaskMeasurements, RefusesAMaskOfAnotherSizeOrWithNothingInside) {
    const Volume scan = scanOn({5, 4, 3});
    EXPECT_THROW(measureMask(scan, std::vector<std::uint8_t>(59, 1)), std::invalid_argument);
    EXPECT_THROW(measureMask(scan, std::vector<std::uint8_t>(60, 0)), std::invalid_argument);
    // One voxel: no extent, every diameter zero, its surface a small closed mesh.
    std::vector<std::uint8_t> one(60, 0);
    one[linearIndex({5, 4, 3}, 2, 2, 1)] = 1;
    const MaskMeasurements m = measureMask(scan, one);
    EXPECT_EQ(m.voxels, 1u);
    EXPECT_EQ(m.axial.longest.lengthMm, 0.0);
    EXPECT_EQ(m.axial.perpendicular.lengthMm, 0.0);
    EXPECT_EQ(m.longest3d.lengthMm, 0.0);
    EXPECT_GT(m.surfaceAreaMm2, 0.0);
}

// The area measured is the area of the mesh the STL and PLY exports write from the mask.
TEST(MaskMeasurements, AreaIsTheExportedMeshsArea) {
    const Volume scan = scanOn({30, 26, 12});
    const Geometry& g = scan.geometry();
    const auto mask = maskWhere(g, [](const glm::dvec3& p) {
        return glm::distance(p, glm::dvec3(10.0, 11.0, 14.0)) <= 8.0;
    });
    const SurfaceMesh mesh = extractSurface(g, maskToField(g, mask));
    EXPECT_DOUBLE_EQ(measureMask(scan, mask).surfaceAreaMm2, surfaceArea(mesh));
}

} // namespace
} // namespace steerseg::test
