// Undo's copies of the level set (level_set_copy.hpp): a handful of buffer copies on the GPU
// each way. A copy keeps the slots as they were, so restoring one refills the pool as an upload
// does and lists and classifies its bricks (replaceLevelSet).
#include "gpu/gl_state_guard.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"

#include <stdexcept>

namespace steerseg::solver {

LevelSetCopy::LevelSetCopy() = default;
LevelSetCopy::~LevelSetCopy() = default;
LevelSetCopy::LevelSetCopy(LevelSetCopy&&) noexcept = default;
LevelSetCopy& LevelSetCopy::operator=(LevelSetCopy&&) noexcept = default;

std::size_t LevelSetCopy::bytes() const {
    return pool_ ? pool_->bytes : 0;
}

void LevelSetSolver::requireCopyOfThis(const LevelSetCopy& copy) const {
    if (!copy.pool_ || copy.dims_ != dims_ || copy.brickSize_ != options_.brickSize) {
        throw std::invalid_argument("solver: the level-set copy is empty or of another grid");
    }
}

LevelSetCopy LevelSetSolver::copyLevelSet() const {
    gpu::GlStateGuard guard;
    LevelSetCopy c;
    c.pool_ = std::make_unique<detail::PoolCopy>(pool_->copy(pool_->readControl()));
    c.dims_ = dims_;
    c.brickSize_ = options_.brickSize;
    return c;
}

void LevelSetSolver::restoreLevelSet(const LevelSetCopy& copy) {
    requireCopyOfThis(copy);
    replaceLevelSet([&] { pool_->restore(*copy.pool_); });
}

std::vector<std::uint8_t> LevelSetSolver::readMask(const LevelSetCopy& copy) const {
    requireCopyOfThis(copy);
    gpu::GlStateGuard guard;
    return pool_->downloadMask(*copy.pool_);
}

} // namespace steerseg::solver
