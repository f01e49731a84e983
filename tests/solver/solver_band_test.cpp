// Which bricks the sparse solver stores: those the narrow band occupies, and constant ones only
// where the band reaches the face they share with a stored brick (settle_bricks requests and
// retires them). The results are the dense reference's either way (the agreement tests); this
// checks the storage is no larger than that.
#include "gpu/gl.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/reference_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class SolverBandTest : public GpuTest {};

std::vector<std::uint32_t> readPageTable(const BrickPoolView& view) {
    const auto count = static_cast<std::size_t>(view.brickGrid.x) *
                       static_cast<std::size_t>(view.brickGrid.y) *
                       static_cast<std::size_t>(view.brickGrid.z);
    std::vector<std::uint32_t> page(count);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, view.pageTableBuffer);
    const void* mapped = glMapBufferRange(GL_SHADER_STORAGE_BUFFER, 0,
                                          static_cast<GLsizeiptr>(count * 4), GL_MAP_READ_BIT);
    EXPECT_NE(mapped, nullptr);
    if (mapped != nullptr) {
        std::memcpy(page.data(), mapped, count * 4);
    }
    glUnmapBuffer(GL_SHADER_STORAGE_BUFFER);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return page;
}

struct BandCount {
    int stored = 0;
    int live = 0;          // holding a voxel with |phi| < kPhiFar
    int reachedOnly = 0;   // uniform, across a face whose other side has such a voxel
    int unexplained = 0;   // stored but neither (what the first version kept)
    int liveNotStored = 0; // would lose phi
};

// Classifies each brick from phi read back on the CPU.
BandCount countBand(const LevelSetSolver& s) {
    const BrickPoolView view = s.poolView();
    const std::vector<std::uint32_t> page = readPageTable(view);
    const std::vector<float> phi = s.readPhi();
    const glm::ivec3 d = view.volumeDims;
    const glm::ivec3 g = view.brickGrid;
    const int b = view.brickSize;
    auto brickOf = [&](const glm::ivec3& br) {
        return static_cast<std::size_t>(br.x + g.x * (br.y + g.y * br.z));
    };
    std::vector<std::uint8_t> live(page.size(), 0);
    std::vector<std::uint8_t> reached(page.size(), 0);
    const std::array<glm::ivec3, 6> faces{glm::ivec3(-1, 0, 0), glm::ivec3(1, 0, 0),
                                          glm::ivec3(0, -1, 0), glm::ivec3(0, 1, 0),
                                          glm::ivec3(0, 0, -1), glm::ivec3(0, 0, 1)};
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                if (std::abs(phi[voxelIndex(d, i, j, k)]) >= kPhiFar) {
                    continue;
                }
                const glm::ivec3 v{i, j, k};
                live[brickOf(v / b)] = 1;
                // The voxel across each face of the grid of voxels, if it lies in another brick.
                for (const glm::ivec3& f : faces) {
                    const glm::ivec3 w = v + f;
                    if (glm::all(glm::greaterThanEqual(w, glm::ivec3(0))) &&
                        glm::all(glm::lessThan(w, d)) && w / b != v / b) {
                        reached[brickOf(w / b)] = 1;
                    }
                }
            }
        }
    }
    BandCount c;
    for (std::size_t n = 0; n < page.size(); ++n) {
        const bool stored = page[n] < kBrickInside;
        c.stored += stored ? 1 : 0;
        c.live += live[n] != 0 ? 1 : 0;
        c.liveNotStored += live[n] != 0 && !stored ? 1 : 0;
        if (stored && live[n] == 0) {
            (reached[n] != 0 ? c.reachedOnly : c.unexplained) += 1;
        }
    }
    std::printf("stored %d bricks: %d live, %d reached only, %d neither\n", c.stored, c.live,
                c.reachedOnly, c.unexplained);
    return c;
}

// A sphere growing in a uniform region and one shrinking under curvature: at any point the
// stored bricks are exactly the live ones plus uniform ones the band reaches across a face.
TEST_F(SolverBandTest, StoresOnlyBricksTheBandOccupiesOrReachesAcrossAFace) {
    const glm::ivec3 d{56, 48, 40};
    LevelSetSolver grow(std::vector<float>(countOf(d), 100.0F), d);
    grow.addSphere({{27.0F, 23.0F, 19.0F}, 4.0F});
    grow.setParams({100.0F, 2.0F, 0.9F});
    for (int chunk = 0; chunk < 3; ++chunk) {
        grow.step(8);
        const BandCount c = countBand(grow);
        EXPECT_EQ(c.liveNotStored, 0);
        EXPECT_EQ(c.unexplained, 0);
        EXPECT_GT(c.live, 0);
    }
    LevelSetSolver shrink(std::vector<float>(countOf(d), 0.0F), d);
    shrink.addSphere({{27.0F, 23.0F, 19.0F}, 14.0F});
    shrink.setParams({0.0F, 0.0F, 0.0F});
    for (int chunk = 0; chunk < 3; ++chunk) {
        shrink.step(40);
        const BandCount c = countBand(shrink);
        EXPECT_EQ(c.liveNotStored, 0);
        EXPECT_EQ(c.unexplained, 0);
        EXPECT_GT(c.live, 0);
    }
}

// Voxels of the mask with a face neighbour on the other side (the volume's edge repeats the
// border voxel, as phiAt does).
std::uint32_t frontOf(const glm::ivec3& d, const std::vector<std::uint8_t>& mask) {
    std::uint32_t front = 0;
    for (int k = 0; k < d.z; ++k) {
        for (int j = 0; j < d.y; ++j) {
            for (int i = 0; i < d.x; ++i) {
                const std::uint8_t side = mask[voxelIndex(d, i, j, k)];
                const std::array<glm::ivec3, 6> faces{{{i - 1, j, k},
                                                       {i + 1, j, k},
                                                       {i, j - 1, k},
                                                       {i, j + 1, k},
                                                       {i, j, k - 1},
                                                       {i, j, k + 1}}};
                bool other = false;
                for (glm::ivec3 n : faces) {
                    n = glm::clamp(n, glm::ivec3(0), d - 1);
                    other = other || mask[voxelIndex(d, n.x, n.y, n.z)] != side;
                }
                front += other ? 1U : 0U;
            }
        }
    }
    return front;
}

// measure_speed measures a brick's front again only where it or a face neighbour changed side
// since it last did (docs/solver.md, Storage): the front it counts is the mask's after every
// step. Every brick awake, so that no sleeping brick's last measure stands in for its own; a
// ball grown across many brick faces, and then shrunk by a new window.
TEST_F(SolverBandTest, TheFrontMeasuredIsTheMasksAtEveryStep) {
    const glm::ivec3 d{40, 36, 32};
    const auto volume = ballVolume(d, 0.0F, 100.0F, {20, 18, 16}, 12.0F);
    SolverOptions options;
    options.sleep = false;
    LevelSetSolver gpu(volume, d, options);
    gpu.addSphere({{19, 17, 15}, 3.0F});
    gpu.setParams({100.0F, 30.0F, 0.7F});
    for (int n = 0; n < 60; ++n) {
        if (n == 40) {
            gpu.setParams({50.0F, 10.0F, 0.7F});
        }
        const auto before = gpu.readMask(); // what the step's measure sees
        gpu.step(1);
        ASSERT_EQ(gpu.stats().frontVoxels, frontOf(d, before)) << "step " << n;
    }
}

} // namespace
} // namespace steerseg::test
