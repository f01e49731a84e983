#include "solver/level_set_solver.hpp"

#include "common/bindings.h"
#include "gpu/gl_counts.hpp"
#include "gpu/gl_error.hpp"
#include "gpu/gl_state_guard.hpp"
#include "gpu/gpu_info.hpp"
#include "gpu/gpu_limits.hpp"
#include "solver/gpu_brick_pool.hpp"
#include "solver/solver_programs.hpp"
#include "solver/speed_on_demand.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::solver {

using detail::groupsOf;
using detail::kAllocArgs;
using detail::kBrickArgs;
using detail::kMeasureArgs;
using detail::kSettleArgs;

namespace {

void setUniform(GLuint program, const char* name, float v) {
    glProgramUniform1f(program, glGetUniformLocation(program, name), v);
}

} // namespace

LevelSetSolver::LevelSetSolver(const Volume& volume, const model::SolverOptions& options)
    : LevelSetSolver(std::make_unique<gpu::ScanTexture>(volume), nullptr, options) {}

LevelSetSolver::LevelSetSolver(std::span<const float> intensities, const glm::ivec3& dims,
                               const model::SolverOptions& options)
    : LevelSetSolver(std::make_unique<gpu::ScanTexture>(intensities, dims), nullptr, options) {}

LevelSetSolver::LevelSetSolver(const gpu::ScanTexture& scan, const model::SolverOptions& options)
    : LevelSetSolver(nullptr, &scan, options) {}

LevelSetSolver::LevelSetSolver(std::unique_ptr<gpu::ScanTexture> own,
                               const gpu::ScanTexture* borrowed,
                               const model::SolverOptions& options)
    : ownScan_(std::move(own)), scan_(ownScan_ ? ownScan_.get() : borrowed), dims_(scan_->dims()),
      sphereScale_(model::sphereScale(scan_->spacing())), options_(options),
      settleWatch_(std::max(options.settleIterations, 1),
                   static_cast<double>(options.settleDisplacement)),
      runawayWatch_(static_cast<double>(options.runawayFactor)) {
    gpu::GlStateGuard guard;
    const glm::ivec3 dims = dims_;
    if (options_.brickSize == 0) {
        options_.brickSize = model::defaultBrickSize();
    }
    const int b = options_.brickSize;
    if (b != 4 && b != 8 && b != 16) {
        throw std::invalid_argument("brick size must be 4, 8 or 16 (got " + std::to_string(b) +
                                    ")");
    }
    const gpu::GpuInfo device = gpu::queryGpuInfo();
    if (options_.groupSize < 0 || options_.groupSize > b * b * b ||
        options_.groupSize > device.maxComputeWorkGroupInvocations) {
        throw std::invalid_argument("groupSize must be 0 (the device's) or 1.." +
                                    std::to_string(b * b * b) +
                                    " and within the device's work-group invocations");
    }
    if (options_.checkInterval < 1) {
        throw std::invalid_argument("checkInterval must be >= 1");
    }
    if (options_.sleepAfter < 1 || options_.sleepAfter > 255 ||
        !(options_.sleepTolerance >= 0.0F)) {
        throw std::invalid_argument("sleepAfter must be 1..255 and sleepTolerance >= 0");
    }
    if (options_.settleIterations < 0 || !(options_.settleDisplacement >= 0.0F) ||
        !(options_.runawayFactor >= 0.0F)) {
        throw std::invalid_argument(
            "settleIterations, settleDisplacement and runawayFactor must be >= 0");
    }
    const std::size_t voxels = static_cast<std::size_t>(dims.x) * static_cast<std::size_t>(dims.y) *
                               static_cast<std::size_t>(dims.z);
    programs_ = std::make_unique<detail::SolverPrograms>(
        b, detail::brickGroupSize(b, options_.groupSize, device.renderer));
    pool_ = std::make_unique<detail::GpuBrickPool>(dims, b, gpu::gpuLimits());
    const glm::ivec3 grid = pool_->brickGrid();
    programs_->forEach([&](gpu::Program& p) {
        glProgramUniform3i(p.id(), glGetUniformLocation(p.id(), "volumeDims"), dims.x, dims.y,
                           dims.z);
        glProgramUniform3i(p.id(), glGetUniformLocation(p.id(), "brickGrid"), grid.x, grid.y,
                           grid.z);
        glProgramUniform3f(p.id(), glGetUniformLocation(p.id(), "sphereScale"), sphereScale_.x,
                           sphereScale_.y, sphereScale_.z);
    });

    glProgramUniform1ui(programs_->buildActiveList.id(),
                        glGetUniformLocation(programs_->buildActiveList.id(), "sleepAfter"),
                        options_.sleep && !options_.dense
                            ? static_cast<GLuint>(options_.sleepAfter)
                            : 256U); // dense: the every-brick baseline
    setUniform(programs_->updatePhi.id(), "sleepTolerance", options_.sleepTolerance);
    glProgramUniform1i(programs_->measureSpeed.id(),
                       glGetUniformLocation(programs_->measureSpeed.id(), "signRows"),
                       options_.frontFromSignRows ? 1 : 0);
    uploadBarriers();
    uploadReach();
    stats_.totalBricks = pool_->brickCount();
    stats_.densePhiBytes = voxels * sizeof(float);
    uploadPhi({}); // everything outside
}

LevelSetSolver::~LevelSetSolver() = default;

void LevelSetSolver::setParams(const model::LevelSetParams& params) {
    const model::TimeStepRule rule = model::timeStepRule(params); // validates
    params_ = params;
    haveParams_ = true;
    for (GLuint p : {programs_->measureSpeed.id(), programs_->updatePhi.id()}) {
        setUniform(p, "alpha", params.alpha);
    }
    // Only measure_speed evaluates the speed (update_phi steps at the speeds it kept).
    setUniform(programs_->measureSpeed.id(), "T", params.T);
    setUniform(programs_->measureSpeed.id(), "eps", params.eps);
    // measure_speed's last group chooses the time step.
    setUniform(programs_->measureSpeed.id(), "courant", rule.courant);
    setUniform(programs_->measureSpeed.id(), "fixedRate", rule.fixedRate);
    uploadBarriers(); // their hold depends on alpha; forgets the speeds the slots kept
    noteChange();
}

void LevelSetSolver::wakeAll() {
    wakePending_ = true;
}

void LevelSetSolver::requireParams() const {
    if (!haveParams_) {
        throw std::logic_error("solver: setParams before stepping");
    }
}

void LevelSetSolver::dispatch(GLuint program, GLuint x, GLuint y, GLuint z) {
    glUseProgram(program);
    gpu::dispatchCompute(x, y, z);
    gpu::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void LevelSetSolver::dispatchIndirect(GLuint program, GLintptr offset) {
    glUseProgram(program);
    gpu::dispatchComputeIndirect(offset);
    gpu::memoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

// Serves pending slot requests and lists the active bricks; build_active_list's last group
// sizes the passes over the lists. `begin`: size the allocation first (begin_iteration), after
// an edit or an upload; within a run the last iteration's settle_bricks did. `evaluateNew`:
// with a speed evaluated on demand, the allocation also evaluates the new bricks' speed (its
// textures bound: bindSpeed).
void LevelSetSolver::allocateAndList(bool begin, bool evaluateNew) {
    auto& p = *programs_;
    if (begin) {
        dispatch(p.beginIteration.id(), 1);
    }
    if (evaluateNew && speedOnDemand()) {
        onDemand_->allocate(kAllocArgs);
    } else {
        dispatchIndirect(p.allocateBricks.id(), kAllocArgs);
    }
    glProgramUniform1ui(p.buildActiveList.id(),
                        glGetUniformLocation(p.buildActiveList.id(), "capacity"),
                        pool_->capacity());
    glProgramUniform1i(p.buildActiveList.id(),
                       glGetUniformLocation(p.buildActiveList.id(), "wakeAll"),
                       wakePending_ ? 1 : 0);
    if (wakePending_) {
        pool_->forgetMeasures(); // what woke them may have changed sides outside a step
    }
    wakePending_ = false;
    dispatch(p.buildActiveList.id(), groupsOf(pool_->capacity(), detail::kSlotsPerGroup));
}

// After the level set changed: the step's shells committed (`step`), bricks' states,
// retirement, and requests for the band's neighbours (served at the start of the next
// iteration), in one pass whose last group prepares that iteration.
void LevelSetSolver::settle(bool step) {
    auto& p = *programs_;
    const GLuint program = p.settleBricks.id();
    ++epoch_;
    glProgramUniform1ui(program, glGetUniformLocation(program, "epoch"), epoch_);
    glProgramUniform1i(program, glGetUniformLocation(program, "commitShells"), step ? 1 : 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "retire"), options_.dense ? 0 : 1);
    dispatchIndirect(program, kSettleArgs);
}

// One iteration as a sequence of named passes (cf. OpenVDB's LevelSetTracker): five dispatches,
// each behind its memory barrier, and no host sync. With a speed evaluated on demand, the
// first iteration after a wake has a sixth: every brick of the band may step then, and those
// allocated before the speed was set (or before an edit) have none yet; later the band's new
// bricks get theirs where they are allocated.
void LevelSetSolver::iterate(float timeLimit) {
    auto& p = *programs_;
    const bool woke = wakePending_;
    allocateAndList(false, true);
    if (speedOnDemand() && woke) {
        onDemand_->evaluateActive(kBrickArgs);
    }
    setUniform(p.measureSpeed.id(), "timeLimit", timeLimit);
    dispatchIndirect(p.measureSpeed.id(), kMeasureArgs);
    dispatchIndirect(p.updatePhi.id(), kBrickArgs);
    settle(true);
}

model::StepResult LevelSetSolver::step(int n) {
    return advance(n, FLT_MAX, false);
}

model::StepResult LevelSetSolver::evolveUntil(float time, int maxIterations) {
    if (!(time >= 0.0F) || !std::isfinite(time)) {
        throw std::invalid_argument("evolution time must be a finite number >= 0");
    }
    return advance(maxIterations, time, false);
}

model::StepResult LevelSetSolver::runUntilConverged(int maxIterations) {
    return advance(maxIterations, FLT_MAX, true);
}

bool LevelSetSolver::converged() const {
    return converged_;
}

std::vector<std::uint8_t> LevelSetSolver::readMask() const {
    gpu::GlStateGuard guard;
    return pool_->downloadMask();
}

std::uint64_t LevelSetSolver::countInside() const {
    gpu::GlStateGuard guard;
    return pool_->countInside();
}

std::vector<float> LevelSetSolver::readPhi() const {
    gpu::GlStateGuard guard;
    return pool_->download();
}

BrickPoolView LevelSetSolver::poolView() const {
    return pool_->view();
}

model::SolverStats LevelSetSolver::stats() const {
    model::SolverStats s = stats_;
    s.iterations = lastIteration_;
    s.evolvedTime = lastTime_;
    s.capacity = pool_->capacity();
    s.levelSetBytes = pool_->levelSetBytes();
    s.bookkeepingBytes = pool_->bookkeepingBytes();
    s.speedBytes = pool_->speedBytes();
    s.barriers = static_cast<int>(barriers_.size());
    s.visitedVoxelsPerIteration =
        lastIteration_ > 0 ? static_cast<double>(s.visitedVoxels) / lastIteration_ : 0.0;
    return s;
}

} // namespace steerseg::solver
