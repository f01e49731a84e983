// The level set's edits: a new start (threshold, mask) and sphere seeds and erasers, each ending
// with the band's bricks classified and the convergence clock restarted.
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/level_set_solver.hpp"
#include "solver/phi_init.hpp"
#include "solver/solver_programs.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace steerseg::solver {

using detail::ControlBlock;
using detail::groupsOf;
using detail::kBrickArgs;

void LevelSetSolver::uploadPhi(std::span<const float> phi) {
    replaceLevelSet([&] { pool_->upload(phi, options_.dense); });
}

void LevelSetSolver::replaceLevelSet(const std::function<void()>& fill) {
    gpu::GlStateGuard guard;
    wakeAll(); // the new slots' states are unset until classify_bricks
    fill();
    pool_->bind();
    allocateAndList(true, false);
    dispatchIndirect(programs_->classifyBricks.id(), kBrickArgs);
    settle(false);
    noteChange();
    stats_.peakLevelSetBytes = std::max(stats_.peakLevelSetBytes, pool_->levelSetBytes());
}

void LevelSetSolver::initFromThreshold(std::span<const float> intensities, float lo, float hi) {
    if (intensities.size() != static_cast<std::size_t>(dims_.x) *
                                  static_cast<std::size_t>(dims_.y) *
                                  static_cast<std::size_t>(dims_.z)) {
        throw std::invalid_argument("solver: intensities do not match the volume's dimensions");
    }
    uploadPhi(maskToPhi(thresholdMask(intensities, lo, hi), dims_));
}

void LevelSetSolver::initFromMask(std::span<const std::uint8_t> mask) {
    uploadPhi(maskToPhi(mask, dims_));
}

void LevelSetSolver::initFromSmoothMask(std::span<const std::uint8_t> mask) {
    uploadPhi(smoothMaskPhi(mask, dims_));
}

void LevelSetSolver::addSphere(const model::Sphere& sphere) {
    editSphere(sphere, true);
}
void LevelSetSolver::removeSphere(const model::Sphere& sphere) {
    editSphere(sphere, false);
}

void LevelSetSolver::editSphere(const model::Sphere& sphere, bool add) {
    model::validateSphere(sphere, dims_);
    gpu::GlStateGuard guard;
    wakeAll(); // the sphere may cover sleeping bricks: classify_bricks must see them
    const int b = options_.brickSize;
    // The voxels within kPhiFar + 1 voxel steps of the sphere (request_edit_bricks' bound).
    const float coarsest = std::max({sphereScale_.x, sphereScale_.y, sphereScale_.z});
    const model::Sphere band{sphere.centre, sphere.radius + coarsest * (model::kPhiFar + 1.0F)};
    const glm::vec3 reach = model::sphereHalfExtent(band, sphereScale_);
    const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor(sphere.centre - reach)) / b,
                                     glm::ivec3(0), pool_->brickGrid() - 1);
    const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::ceil(sphere.centre + reach)) / b,
                                     glm::ivec3(0), pool_->brickGrid() - 1);
    const glm::ivec3 size = hi - lo + 1;
    const auto boxBricks = static_cast<std::uint32_t>(size.x * size.y * size.z);
    // Make room for every brick of the box up front: an edit must not stall half-applied.
    ControlBlock ctrl = pool_->readControl();
    const std::uint32_t used = pool_->usedSlots(ctrl);
    if (ctrl.freeCount < boxBricks + ctrl.requestCount) {
        const std::uint32_t want = used + boxBricks + ctrl.requestCount;
        pool_->grow(want + want / 4, ctrl);
        ++stats_.poolGrowths;
        stats_.peakLevelSetBytes = std::max(stats_.peakLevelSetBytes, pool_->levelSetBytes());
    }
    pool_->bind();
    auto& p = *programs_;
    const GLuint req = p.requestEditBricks.id();
    const GLuint apply = p.applySphere.id();
    for (GLuint prog : {req, apply}) {
        glProgramUniform3i(prog, glGetUniformLocation(prog, "boxMin"), lo.x, lo.y, lo.z);
        glProgramUniform3i(prog, glGetUniformLocation(prog, "boxSize"), size.x, size.y, size.z);
        glProgramUniform3f(prog, glGetUniformLocation(prog, "centre"), sphere.centre.x,
                           sphere.centre.y, sphere.centre.z);
        glProgramUniform1f(prog, glGetUniformLocation(prog, "radius"), sphere.radius);
        glProgramUniform1i(prog, glGetUniformLocation(prog, "addMode"), add ? 1 : 0);
    }
    glProgramUniform1ui(req, glGetUniformLocation(req, "epoch"), epoch_);
    dispatch(req, groupsOf(static_cast<std::uint32_t>(size.x), 4),
             groupsOf(static_cast<std::uint32_t>(size.y), 4),
             groupsOf(static_cast<std::uint32_t>(size.z), 4));
    allocateAndList(true, false);
    if (pool_->readControl().stalled != 0) {
        throw gpu::GpuCapacityError("the sphere edit needs more bricks than " +
                                    pool_->capacityLimitText());
    }
    dispatch(apply, static_cast<GLuint>(size.x), static_cast<GLuint>(size.y),
             static_cast<GLuint>(size.z));
    dispatchIndirect(p.classifyBricks.id(), kBrickArgs);
    settle(false);
    noteChange();
    gpu::checkGl("sphere edit");
}

// An edit or a parameter change restarts the convergence clock, and the baseline of the pool's
// growth estimate (managePool): an edit's bricks are not the band's advance. It wakes every
// brick: what made a brick sleep may no longer hold.
void LevelSetSolver::noteChange() {
    wakeAll();
    ControlBlock ctrl = pool_->readControl();
    // What changed side since the last check (a sphere edit's voxels, or steps that ended
    // between checks) is the front's no longer, but the inside count's all the same.
    stats_.netGained +=
        static_cast<std::int64_t>(ctrl.gained) - static_cast<std::int64_t>(ctrl.lost);
    lastUsed_ = pool_->usedSlots(ctrl);
    ctrl.lastChange = ctrl.iteration;
    ctrl.lastChangeTime = ctrl.time;
    detail::clearGrowth(ctrl);
    pool_->writeControl(ctrl);
    known_ = ctrl;
    converged_ = false;
    settled_ = false;
    leakWatch_.reset();
    settleWatch_.reset();
    runawayWatch_.reset();
    checkOrigin_.reset();
}

void LevelSetSolver::holdBarrier(const model::Barrier& barrier) {
    model::validateBarrier(barrier, dims_);
    if (barriers_.size() >= model::kMaxBarriers) {
        throw std::invalid_argument("at most " + std::to_string(model::kMaxBarriers) +
                                    " barriers (clear them to place others)");
    }
    barriers_.push_back(barrier);
    uploadBarriers();
    noteChange(); // the speed changed around it
}

void LevelSetSolver::addBarrier(const model::Barrier& barrier) {
    holdBarrier(barrier);
    // The sphere takes its side at once, as a seed or an erase would.
    if (barrier.keep) {
        addSphere(barrier.sphere);
    } else {
        removeSphere(barrier.sphere);
    }
}

void LevelSetSolver::clearBarriers() {
    barriers_.clear();
    uploadBarriers();
    noteChange();
}

void LevelSetSolver::setBox(const std::optional<model::Box>& box) {
    if (box) {
        model::validateBox(*box, dims_);
    }
    if (box == box_) {
        return;
    }
    box_ = box;
    uploadBarriers();
    noteChange(); // a box that shrank: the surface outside it recedes from every brick
}

void LevelSetSolver::setReach(const std::optional<model::Reach>& reach) {
    if (reach) {
        model::validateSphere(reach->sphere, dims_);
    }
    reach_ = reach;
    uploadReach();
    noteChange(); // a wider reach wakes what it takes in
}

void LevelSetSolver::uploadReach() {
    const GLuint p = programs_->updatePhi.id();
    const model::Reach r = reach_.value_or(model::Reach{}); // radius 0: everywhere
    const model::Sphere& s = r.sphere;
    glProgramUniform4f(p, glGetUniformLocation(p, "reach"), s.centre.x, s.centre.y, s.centre.z,
                       s.radius);
    glProgramUniform1i(p, glGetUniformLocation(p, "recedeOutside"), r.recedeOutside ? 1 : 0);
    // Beyond a receding reach the surface still withdraws: only a plain one holds it there.
    const GLuint list = programs_->buildActiveList.id();
    glProgramUniform4f(list, glGetUniformLocation(list, "heldBeyond"), s.centre.x, s.centre.y,
                       s.centre.z, r.recedeOutside ? 0.0F : s.radius);
}

// Sets the barrier uniforms of the pass that evaluates the speed (barrier_speed.glsl), whose
// values the slots kept for the old barriers (or alpha) then no longer hold.
void LevelSetSolver::uploadBarriers() {
    std::vector<float> packed;
    std::vector<float> levels; // level, reach (0: none)
    for (const model::Barrier& b : barriers_) {
        // The shader tells a keeping sphere by its negative radius.
        const model::Sphere& s = b.sphere;
        packed.insert(packed.end(),
                      {s.centre.x, s.centre.y, s.centre.z, b.keep ? -s.radius : s.radius});
        const model::TissueLevel t = b.tissue.value_or(model::TissueLevel{});
        levels.insert(levels.end(), {t.level, t.reach});
    }
    // alpha * hold = 1 + 3 (1 - alpha) outweighs the curvature term's pull (at most a few
    // voxels^-1 on a voxel-scale bump), so the front recedes from a blocking barrier and
    // advances through a keeping one. alpha = 0 has no
    // data term for a barrier to act through.
    const float alpha = haveParams_ ? params_.alpha : 1.0F;
    const float hold = alpha > 0.0F ? (1.0F + 3.0F * (1.0F - alpha)) / alpha : 0.0F;
    const GLuint p = programs_->measureSpeed.id();
    glProgramUniform1i(p, glGetUniformLocation(p, "barrierCount"),
                       static_cast<GLint>(barriers_.size()));
    if (!barriers_.empty()) {
        glProgramUniform4fv(p, glGetUniformLocation(p, "barriers"),
                            static_cast<GLsizei>(barriers_.size()), packed.data());
        glProgramUniform2fv(p, glGetUniformLocation(p, "barrierLevels"),
                            static_cast<GLsizei>(barriers_.size()), levels.data());
    }
    glProgramUniform1f(p, glGetUniformLocation(p, "barrierHold"), hold);
    // No box: one that holds every voxel index.
    const model::Box box = box_.value_or(model::Box{glm::ivec3(0), dims_ - 1});
    glProgramUniform3i(p, glGetUniformLocation(p, "boxLo"), box.lo.x, box.lo.y, box.lo.z);
    glProgramUniform3i(p, glGetUniformLocation(p, "boxHi"), box.hi.x, box.hi.y, box.hi.z);
    gpu::GlStateGuard guard;
    pool_->forgetSpeed();
}

} // namespace steerseg::solver
