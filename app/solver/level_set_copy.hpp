#pragma once

// A copy of the solver's level set kept in GPU memory: undo's snapshots (docs/steering.md).
// LevelSetSolver::copyLevelSet takes it in a few buffer copies on the GPU, where reading the
// level set back and turning it into a mask cost a 256^3 scan ~70 ms a time on llvmpipe, and
// restoreLevelSet gives back exactly the phi copied (a mask only gives back its voxels). Names
// no GL type; its buffers are freed when it is destroyed, which needs the context current.
#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>

namespace steerseg::solver {

namespace detail {
struct PoolCopy;
} // namespace detail

class LevelSetCopy {
  public:
    LevelSetCopy();
    ~LevelSetCopy();
    LevelSetCopy(LevelSetCopy&&) noexcept;
    LevelSetCopy& operator=(LevelSetCopy&&) noexcept;

    // GPU memory held: the pool's phi and its tables.
    [[nodiscard]] std::size_t bytes() const;

  private:
    friend class LevelSetSolver;
    std::unique_ptr<detail::PoolCopy> pool_;
    glm::ivec3 dims_{0};
    int brickSize_ = 0;
};

} // namespace steerseg::solver
