// A scan, level set or picture larger than the GPU holds is refused before anything is
// allocated, with one line naming the limit and the numbers (docs/large-scans.md). The limits
// are lowered through gpu::TestGpuLimits, so the real checks and allocations run on a small
// volume in the real context.
#include "gpu/gl_error.hpp"
#include "gpu/gpu_limits.hpp"
#include "gpu/scan_texture.hpp"
#include "render/renderer.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"
#include "support/gpu_fixture.hpp"
#include "support/solver_test_support.hpp"

#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
using namespace steerseg::solver; // the solver under test
using namespace steerseg::model;
namespace {

class GpuLimitsTest : public GpuTest {};

constexpr glm::ivec3 kDims{48, 48, 40}; // 6x6x5 = 180 bricks of 8^3

// Runs f, which must throw gpu::GpuCapacityError; returns its message.
template <typename F> std::string capacityError(F&& f) {
    try {
        f();
    } catch (const gpu::GpuCapacityError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no GpuCapacityError";
    return {};
}

TEST_F(GpuLimitsTest, LoweredLimitsApplyWhileInForceOnly) {
    const gpu::GpuLimits context = gpu::gpuLimits();
    EXPECT_GE(context.max3dTextureSize, 256); // GLES 3.1 minimums
    EXPECT_GE(context.maxShaderStorageBlockBytes, std::size_t{1} << 24);
    EXPECT_GE(context.maxComputeWorkGroupCount[0], 65535U);
    {
        gpu::GpuLimits lower;
        lower.max3dTextureSize = 32;
        const gpu::TestGpuLimits in(lower);
        EXPECT_EQ(gpu::gpuLimits().max3dTextureSize, 32);
        EXPECT_EQ(gpu::gpuLimits().maxTextureSize, context.maxTextureSize); // 0: kept
    }
    EXPECT_EQ(gpu::gpuLimits().max3dTextureSize, context.max3dTextureSize);
}

TEST_F(GpuLimitsTest, ScanTextureRefusesAScanPastThe3dTextureSize) {
    const std::vector<float> volume(countOf(kDims), 100.0F);
    gpu::GpuLimits lower;
    lower.max3dTextureSize = 44;
    const gpu::TestGpuLimits in(lower);
    EXPECT_EQ(capacityError([&] { gpu::ScanTexture t(volume, kDims); }),
              "scan 48x48x40 exceeds GL_MAX_3D_TEXTURE_SIZE 44 of this GPU");
    lower.max3dTextureSize = 48; // exactly the largest side: fits
    const gpu::TestGpuLimits fits(lower);
    EXPECT_NO_THROW(gpu::ScanTexture(volume, kDims));
}

TEST_F(GpuLimitsTest, SolverRefusesAPageTablePastTheStorageBlockSize) {
    const std::vector<float> volume(countOf(kDims), 100.0F);
    gpu::GpuLimits lower;
    lower.maxShaderStorageBlockBytes = 512; // 180 bricks' page table is 720 bytes
    const gpu::TestGpuLimits in(lower);
    EXPECT_EQ(capacityError([&] { LevelSetSolver s(volume, kDims); }),
              "level set of 48x48x40 (180 bricks of 8^3): its page table (720 bytes) exceeds "
              "GL_MAX_SHADER_STORAGE_BLOCK_SIZE 512 bytes of this GPU");
}

TEST_F(GpuLimitsTest, SolverRefusesMoreBricksPerAxisThanADispatchReaches) {
    const std::vector<float> volume(countOf(kDims), 100.0F);
    gpu::GpuLimits lower;
    lower.maxComputeWorkGroupCount[2] = 4;
    const gpu::TestGpuLimits in(lower);
    EXPECT_EQ(capacityError([&] { LevelSetSolver s(volume, kDims); }),
              "level set of 48x48x40 (180 bricks of 8^3): 5 bricks along axis 2 exceed "
              "GL_MAX_COMPUTE_WORK_GROUP_COUNT[2] 4 of this GPU");
}

// A front that grows past the pool the storage block holds stops with the limit named, and
// the same run under the context's own limits does not.
TEST_F(GpuLimitsTest, AFrontOutgrowingTheStorageBlockStopsWithTheLimitNamed) {
    const std::vector<float> volume(countOf(kDims), 100.0F);
    const LevelSetParams grow{100.0F, 5.0F, 1.0F};
    const Sphere seed{{24.0F, 24.0F, 20.0F}, 2.0F};
    {
        LevelSetSolver free(volume, kDims);
        free.addSphere(seed);
        free.setParams(grow);
        EXPECT_NO_THROW(free.step(60));
        EXPECT_GT(free.stats().capacity, 40U); // the run below needs more than its 40 slots
    }
    gpu::GpuLimits lower;
    lower.maxShaderStorageBlockBytes = 40 * 2320; // 40 bricks' speeds, headers and sign rows
    const gpu::TestGpuLimits in(lower);
    LevelSetSolver bound(volume, kDims);
    bound.addSphere(seed);
    bound.setParams(grow);
    EXPECT_EQ(capacityError([&] { bound.step(60); }),
              "the level set outgrew 40 bricks (91 KiB of their kept speeds), the most "
              "GL_MAX_SHADER_STORAGE_BLOCK_SIZE 91 KiB of this GPU holds");
}

// 512x512x256 has 131,072 bricks: a pass over the slots, 64 to a work group, reaches 65,536
// of them with 1024 groups. Only the page table and the per-brick buffers are allocated.
TEST_F(GpuLimitsTest, ThePoolStopsWhereItsDispatchWouldPassTheWorkGroupCount) {
    gpu::GpuLimits limits = gpu::gpuLimits();
    limits.maxShaderStorageBlockBytes = std::size_t{1} << 30;
    limits.maxComputeWorkGroupCount[0] = 1024;
    const detail::GpuBrickPool pool({512, 512, 256}, 8, limits);
    EXPECT_EQ(pool.brickCount(), 131072U);
    EXPECT_EQ(pool.maxCapacity(), 65536U);
    EXPECT_EQ(pool.capacityLimitText(),
              "65536 bricks, the most GL_MAX_COMPUTE_WORK_GROUP_COUNT[0] 1024 of this GPU "
              "reaches at 64 slots per work group");
    limits.maxComputeWorkGroupCount[0] = 1023; // the 2D passes' rows are 1024 groups wide
    EXPECT_NE(capacityError([&] {
                  detail::GpuBrickPool p({512, 512, 256}, 8, limits);
              }).find("more than GL_MAX_COMPUTE_WORK_GROUP_COUNT 1023x"),
              std::string::npos);
}

TEST_F(GpuLimitsTest, RendererRefusesAPicturePastTheTextureSize) {
    Geometry g;
    g.dims = {32, 32, 32};
    Volume scan(VoxelType::Float32, g);
    render::Renderer renderer(scan);
    gpu::GpuLimits lower;
    lower.maxTextureSize = 256;
    const gpu::TestGpuLimits in(lower);
    const render::ViewParams p = renderer.defaultParams(render::ViewKind::Axial, {320, 200});
    EXPECT_EQ(capacityError([&] { renderer.render(p, nullptr); }),
              "picture 320x200 exceeds GL_MAX_TEXTURE_SIZE 256 of this GPU");
    const render::ViewParams fits = renderer.defaultParams(render::ViewKind::Axial, {256, 200});
    EXPECT_NO_THROW(renderer.render(fits, nullptr));
}

} // namespace
} // namespace steerseg::test
