#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "solver/brick_pool_view.hpp"
#include "solver/control_block.hpp"
#include "solver/level_set_params.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace steerseg {

namespace solver_detail {
class GpuBrickPool;
struct SolverPrograms;
} // namespace solver_detail

// Brick edge in voxels. Measured on llvmpipe (2 cores, bench/solver_bench): see kDefaultBrickSize
// in level_set_solver.cpp for the figures.
int defaultBrickSize();

struct SolverOptions {
    int brickSize = 0;      // 0: defaultBrickSize(); 4, 8 or 16
    bool dense = false;     // every brick active, never retired (benchmark baseline)
    int checkInterval = 16; // iterations between reads of the GPU's counters
    // Converged: no voxel changed side for convergeIterations iterations spanning at least
    // convergeTime of evolution, or for 10 * convergeIterations iterations (a front held by a
    // strongly negative speed elsewhere takes tiny steps).
    int convergeIterations = 20;
    float convergeTime = 0.5F;
};

// Why a step call returned.
enum class StopReason {
    IterationLimit, // the call's iteration count (step) or maxIterations ran out first
    TimeReached,    // evolveUntil's time was reached (the last step cut to land on it)
    Converged,      // runUntilConverged: converged() holds
};
// "iteration_limit", "time_reached", "converged" (the segment report's stop_reason).
const char* stopReasonName(StopReason reason);

struct StepResult {
    int iterations = 0;       // performed by this call
    float evolvedTime = 0.0F; // total since the start
    bool converged = false;   // converged() after the call, whatever stopped it
    StopReason stopReason = StopReason::IterationLimit;
};

struct SolverStats {
    int iterations = 0;
    float evolvedTime = 0.0F;
    std::uint32_t activeBricks = 0; // bricks processed in the last iteration
    std::uint32_t peakActiveBricks = 0;
    std::uint32_t totalBricks = 0;
    std::uint32_t capacity = 0;    // pool slots
    std::size_t levelSetBytes = 0; // phi pool + shell scratch + page table, now
    std::size_t peakLevelSetBytes = 0;
    std::size_t bookkeepingBytes = 0; // slot map, lists, states
    std::size_t densePhiBytes = 0;    // one float per voxel, for comparison
    int poolGrowths = 0;
    int poolShrinks = 0;
    int stalls = 0; // chunks that ran out of slots before a growth
};

// The sparse packed-brick level-set solver (GLES 3.1 compute). Needs a current GL context for
// its whole life. The scan is uploaded once as an R32F 3D texture; phi lives in a brick pool
// that grows and shrinks with the surface. Per iteration the CPU only issues dispatches; it
// reads a few counters every checkInterval iterations (pool size, progress, convergence).
class LevelSetSolver {
  public:
    LevelSetSolver(const Volume& volume, const SolverOptions& options = {});
    LevelSetSolver(std::span<const float> intensities, const glm::ivec3& dims,
                   const SolverOptions& options = {});
    ~LevelSetSolver();
    LevelSetSolver(const LevelSetSolver&) = delete;
    LevelSetSolver& operator=(const LevelSetSolver&) = delete;

    // Validated (std::invalid_argument); may change between any two iterations.
    void setParams(const LevelSetParams& params);
    // Sphere edits (voxel indices, radius in voxels), between any two iterations.
    void addSphere(const Sphere& sphere);
    void removeSphere(const Sphere& sphere);
    // Replace the level set.
    void initFromThreshold(float lo, float hi);
    void initFromMask(std::span<const std::uint8_t> mask);

    // n iterations (fewer never: a pool that runs out is grown and the rest re-run).
    StepResult step(int n);
    // Until the summed time step reaches `time` (the last step is cut to land on it) or
    // maxIterations.
    StepResult evolveUntil(float time, int maxIterations);
    // Until converged() or maxIterations.
    StepResult runUntilConverged(int maxIterations);
    [[nodiscard]] bool converged() const;

    // 1 inside (phi < 0), i fastest; reads the level set back (not per iteration).
    [[nodiscard]] std::vector<std::uint8_t> readMask() const;
    [[nodiscard]] std::vector<float> readPhi() const;

    // The level set for readers (renderer); valid until the next step or edit.
    [[nodiscard]] BrickPoolView poolView() const;
    // The scan as uploaded (R32F 3D texture, real units), for the renderer.
    [[nodiscard]] GLuint scanTexture() const { return scan_.id(); }
    [[nodiscard]] SolverStats stats() const;
    [[nodiscard]] const glm::ivec3& dims() const { return dims_; }

  private:
    StepResult advance(int maxIterations, float timeLimit, bool untilConverged);
    void iterate(float timeLimit);
    void allocateAndList();
    void settle();
    void editSphere(const Sphere& sphere, bool add);
    void uploadPhi(const std::vector<float>& phi);
    void noteChange();
    bool managePool(const solver_detail::ControlBlock& ctrl);
    void dispatch(GLuint program, GLuint x, GLuint y = 1, GLuint z = 1);
    void dispatchIndirect(GLuint program, GLintptr offset);
    void requireParams() const;

    glm::ivec3 dims_;
    SolverOptions options_;
    std::vector<float> intensities_; // CPU copy for threshold initialisation
    std::unique_ptr<solver_detail::SolverPrograms> programs_;
    std::unique_ptr<solver_detail::GpuBrickPool> pool_;
    gpu::Texture scan_;
    LevelSetParams params_;
    bool haveParams_ = false;
    std::uint32_t epoch_ = 1;
    SolverStats stats_;
    float lastTime_ = 0.0F;
    int lastIteration_ = 0;
    std::uint32_t lastUsed_ = 0;                       // used slots at the last pool check
    std::optional<solver_detail::ControlBlock> known_; // the GPU's control block, when known
    bool converged_ = false;
};

} // namespace steerseg
