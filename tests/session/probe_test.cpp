// The probe (session/probe.hpp) leaves out one stray voxel for T and eps, and keeps it for a
// tissue's level.
#include "session/probe.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

// 3 mm voxels of soft tissue (20 +- 10 in a checker) and, at (5, 4, 4), one voxel of contrast.
Volume tissueWithContrast() {
    Geometry g;
    g.dims = {9, 9, 9};
    g.spacing = {3.0, 3.0, 3.0};
    Volume v(VoxelType::Float32, g);
    const auto out = v.voxels<float>();
    for (int k = 0; k < 9; ++k) {
        for (int j = 0; j < 9; ++j) {
            for (int i = 0; i < 9; ++i) {
                out[v.linearIndex(i, j, k)] = (i + j + k) % 2 == 0 ? 30.0F : 10.0F;
            }
        }
    }
    out[v.linearIndex(5, 4, 4)] = 600.0F;
    return v;
}

TEST(Probe, LeavesOutOneStrayVoxelForTheSpeed) {
    const Volume v = tissueWithContrast();
    // 5 mm at 3 mm: the centre, its 6 face and 12 edge neighbours.
    const session::ProbeStats probe = session::probe(v, {4.0, 4.0, 4.0}, 5.0);
    EXPECT_EQ(probe.count, 18U);
    EXPECT_EQ(probe.leftOut, 1U);
    // Left: the centre (30), 5 face neighbours (10), 12 edge neighbours (30).
    EXPECT_DOUBLE_EQ(probe.mean, (13 * 30.0 + 5 * 10.0) / 18.0);
    const double var = (13 * 30.0 * 30.0 + 5 * 10.0 * 10.0) / 18.0 - probe.mean * probe.mean;
    EXPECT_NEAR(probe.stddev, std::sqrt(var), 1e-9);

    const session::ProbeStats level = session::probe(v, {4.0, 4.0, 4.0}, 5.0, session::Stray::Keep);
    EXPECT_EQ(level.count, 19U);
    EXPECT_EQ(level.leftOut, 0U);
    EXPECT_DOUBLE_EQ(level.mean, (13 * 30.0 + 5 * 10.0 + 600.0) / 19.0);
    EXPECT_GT(level.stddev, 5.0 * probe.stddev);
}

} // namespace
} // namespace steerseg::test
