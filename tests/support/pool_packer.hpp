#pragma once

#include "gpu/gl_handle.hpp"
#include "solver/brick_pool_view.hpp"

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace steerseg::test {

// TEST ONLY: packs a dense phi into the brick-pool layout of shaders/common/brick_pool.glsl
// (page table + pool), so renderer tests can draw a known level set without the solver.
// Bricks whose voxels are all <= -phiFar (>= phiFar) become BRICK_INSIDE (BRICK_OUTSIDE); the
// others get pool slots in scan order. phi is clamped to [-phiFar, phiFar].
struct PackedPool {
    std::vector<std::uint32_t> pageTable;
    std::vector<float> pool;
    glm::ivec3 dims{0};
    glm::ivec3 brickGrid{0};
    int brickSize = 8;
    float phiFar = 4.0F;
};
PackedPool packPhi(const std::vector<float>& phi, const glm::ivec3& dims, int brickSize,
                   float phiFar);

// Dense phi from a function of the voxel index.
std::vector<float> densePhi(const glm::ivec3& dims, const std::function<float(glm::ivec3)>& f);

// The packed pool uploaded to SSBOs; view() is what the solver's poolView() would return.
class GpuPool {
  public:
    explicit GpuPool(const PackedPool& packed);
    [[nodiscard]] solver::BrickPoolView view() const;
    [[nodiscard]] std::size_t pooledBricks() const { return pooledBricks_; }

  private:
    gpu::Buffer pageTable_;
    gpu::Buffer pool_;
    solver::BrickPoolView view_;
    std::size_t pooledBricks_ = 0;
};

} // namespace steerseg::test
