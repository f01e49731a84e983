#pragma once

#include "core/volume.hpp"
#include "gpu/gl_handle.hpp"
#include "gpu/scan_texture.hpp"
#include "model/box.hpp"
#include "model/level_set_params.hpp"
#include "model/solver_types.hpp"
#include "solver/brick_pool_view.hpp"
#include "solver/control_block.hpp"
#include "solver/front_check.hpp"
#include "solver/leak_watch.hpp"
#include "solver/level_set_copy.hpp"
#include "solver/runaway_watch.hpp"
#include "solver/settle_watch.hpp"
#include "speed/speed_inputs.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace steerseg::solver {

namespace detail {
class GpuBrickPool;
struct SolverPrograms;
class SpeedOnDemand;
} // namespace detail

// The sparse packed-brick level-set solver (GLES 3.1 compute). Needs a current GL context for
// its whole life. It reads the scan from a gpu::ScanTexture; phi lives in a brick pool that
// grows and shrinks with the surface. Per iteration the CPU only issues dispatches; it reads a
// few counters every checkInterval iterations (pool size, progress, convergence). Every call
// that issues GL work restores the GL state it found (gpu::GlStateGuard).
class LevelSetSolver {
  public:
    // Borrows the scan on the GPU (shared with the renderer); it must outlive the solver.
    explicit LevelSetSolver(const gpu::ScanTexture& scan, const model::SolverOptions& options = {});
    // Upload and own the scan's texture (tests, benchmarks, a solver with no renderer).
    explicit LevelSetSolver(const Volume& volume, const model::SolverOptions& options = {});
    LevelSetSolver(std::span<const float> intensities, const glm::ivec3& dims,
                   const model::SolverOptions& options = {});
    ~LevelSetSolver();
    LevelSetSolver(const LevelSetSolver&) = delete;
    LevelSetSolver& operator=(const LevelSetSolver&) = delete;

    // Validated (std::invalid_argument); may change between any two iterations.
    void setParams(const model::LevelSetParams& params);
    // Wakes every sleeping brick at the next iteration. Anything that changes the speed or
    // the level set outside a step must call it (setParams, edits, barriers and uploads do):
    // a sleeping brick's phi and its time-step bound are only valid for the speed it last saw.
    // The speed changes only through setParams, setSpeedInputs and the barriers, which also
    // forget the speeds each brick keeps between steps (shaders/solver/speed_cache.glsl).
    void wakeAll();
    // What the data term reads (speed::SpeedInputs, docs/speed.md); by default the threshold
    // speed on the raw scan. The textures are borrowed: they must stay alive, and as they
    // were, while the solver steps with them (it keeps the speeds it read: set the inputs
    // again after writing to one). A change restarts the convergence clock and the leak watch, as
    // setParams does. std::invalid_argument for inputs speed::validateSpeedInputs refuses.
    void setSpeedInputs(const speed::SpeedInputs& inputs);
    [[nodiscard]] const speed::SpeedInputs& speedInputs() const { return speedInputs_; }
    // With a speed evaluated on demand (inputs.onDemand): evaluates up to maxBricks more bricks
    // ahead of the front, in index order, so that a view of the speed fills in over a few
    // frames; returns how many bricks remain (0: the factor texture is complete, as it is at
    // once for any other speed).
    std::uint32_t evaluateSpeedAhead(std::uint32_t maxBricks);
    // With a speed evaluated on demand: the bricks whose speed has been computed since it was
    // set (where the front went, and any filled ahead); 0 for a speed computed everywhere. One
    // word read back from the GPU: for reports, not per frame (stats() reads nothing back).
    [[nodiscard]] std::uint32_t speedBricksEvaluated() const;
    // Sphere edits (voxel indices, radius in voxels along the finest axis: model::Sphere),
    // between any two iterations.
    void addSphere(const model::Sphere& sphere);
    void removeSphere(const model::Sphere& sphere);
    // Barriers: spheres the surface may not enter (a leak's neck) or may not leave (a kept
    // correction) for the rest of the run (shaders/solver/barrier_speed.glsl). Adding one also
    // cuts the surface out of a blocking sphere, or fills a keeping one, at once. At most
    // kMaxBarriers (std::invalid_argument beyond, or for a sphere validateSphere refuses).
    void addBarrier(const model::Barrier& barrier);
    // The same without painting the sphere, for one painted on its side just before (a
    // correction paints its sphere, then holds it): painting it again changes no voxel, and an
    // edit's pass over the band cost llvmpipe ~40-100 ms on a 256^3 brain.
    void holdBarrier(const model::Barrier& barrier);
    void clearBarriers();
    [[nodiscard]] const std::vector<model::Barrier>& barriers() const { return barriers_; }
    // The operator's box (model::Box): outside it the speed blocks as a barrier's does, so the
    // surface never leaves it and recedes into a box that shrank. nullopt: no box.
    // std::invalid_argument for a box validateBox refuses.
    void setBox(const std::optional<model::Box>& box);
    [[nodiscard]] const std::optional<model::Box>& box() const { return box_; }
    // Voxels other structures hold (non-zero = claimed, one byte per voxel of the scan, i
    // fastest): the surface never enters them, as a blocking barrier's sphere
    // (barrier_speed.glsl); an empty span clears it, and so does one with no voxel claimed.
    // std::invalid_argument for a span of another size. Not part of the level set: copies,
    // restores, parameters and speeds leave it as it is until it is set again.
    void setClaimed(std::span<const std::uint8_t> claimed);
    [[nodiscard]] bool hasClaimed() const { return static_cast<bool>(claimed_); }
    // Voxels the surface never leaves (non-zero = kept, as setClaimed's): the speed keeps there
    // as a keeping barrier's sphere does. What an erase's run may not take back (the workflow
    // sets the deep part of the surface it starts from: docs/steering.md); an empty span, or one
    // with no voxel kept, clears it. std::invalid_argument for a span of another size. Not part
    // of the level set, as the claimed voxels are not.
    void setKept(std::span<const std::uint8_t> kept);
    [[nodiscard]] bool hasKept() const { return static_cast<bool>(kept_); }
    // Where the surface may move (shaders/solver/update_phi.comp): a sphere, for a correction's
    // run, which should change the surface around the correction and leave the rest as the
    // operator accepted it (or only withdraw there: model::Reach); nullopt: everywhere.
    // Validated as a sphere (std::invalid_argument).
    void setReach(const std::optional<model::Reach>& reach);
    // Replace the level set.
    // `intensities`: the scan's real-unit values, i fastest (the solver keeps no host copy).
    void initFromThreshold(std::span<const float> intensities, float lo, float hi);
    void initFromMask(std::span<const std::uint8_t> mask);
    // The same voxels inside, from smoothMaskPhi: a surface rounded off between them, for a
    // mask that stands for a smooth surface (a file, an autosave) and is drawn as one.
    void initFromSmoothMask(std::span<const std::uint8_t> mask);

    // n iterations (fewer never: a pool that runs out is grown and the rest re-run).
    model::StepResult step(int n);
    // Until the summed time step reaches `time` (the last step is cut to land on it) or
    // maxIterations.
    model::StepResult evolveUntil(float time, int maxIterations);
    // Until converged() or maxIterations.
    model::StepResult runUntilConverged(int maxIterations);
    [[nodiscard]] bool converged() const;

    // Undo's copies (LevelSetCopy): taken on the GPU, restored exactly, barriers, reach and
    // parameters left as they are. std::invalid_argument for a copy of another solver's grid.
    [[nodiscard]] LevelSetCopy copyLevelSet() const;
    void restoreLevelSet(const LevelSetCopy& copy);

    // 1 inside (phi < 0), i fastest; reads the level set back (not per iteration), or a copy.
    [[nodiscard]] std::vector<std::uint8_t> readMask() const;
    [[nodiscard]] std::vector<std::uint8_t> readMask(const LevelSetCopy& copy) const;
    [[nodiscard]] std::vector<float> readPhi() const;
    // Voxels inside (phi < 0) without a dense read-back: the volume after an edit.
    [[nodiscard]] std::uint64_t countInside() const;

    // The level set for readers (renderer); valid until the next step or edit.
    [[nodiscard]] BrickPoolView poolView() const;
    [[nodiscard]] const gpu::ScanTexture& scan() const { return *scan_; }
    [[nodiscard]] model::SolverStats stats() const;
    [[nodiscard]] const glm::ivec3& dims() const { return dims_; }
    // What a sphere's radius is measured in on this scan (model::sphereScale).
    [[nodiscard]] glm::vec3 sphereScale() const { return sphereScale_; }
    // Called with every check's counters (benchmarks record series for tests/data/growth);
    // an empty function stops it.
    void setCheckObserver(std::function<void(const FrontCheck&)> observer) {
        checkObserver_ = std::move(observer);
    }

  private:
    LevelSetSolver(std::unique_ptr<gpu::ScanTexture> own, const gpu::ScanTexture* borrowed,
                   const model::SolverOptions& options);
    model::StepResult advance(int maxIterations, float timeLimit, bool untilConverged);
    void iterate(float timeLimit);
    [[nodiscard]] bool speedOnDemand() const;
    void bindSpeed() const;
    void allocateAndList(bool begin, bool evaluateNew);
    void settle(bool step);
    void editSphere(const model::Sphere& sphere, bool add);
    // A dense phi, or empty: everything outside.
    void uploadPhi(std::span<const float> phi);
    // Fills the pool by `fill` (an upload, a copy restored) and lists and classifies its bricks.
    void replaceLevelSet(const std::function<void()>& fill);
    void requireCopyOfThis(const LevelSetCopy& copy) const;
    void noteChange();
    void uploadBarriers();
    void uploadReach();
    // The leak watch's and the settle watch's check; sets settled_.
    std::optional<model::LeakSite> watchGrowth(detail::ControlBlock& ctrl);
    void takeVisits(detail::ControlBlock& ctrl);
    bool managePool(const detail::ControlBlock& ctrl);
    void dispatch(GLuint program, GLuint x, GLuint y = 1, GLuint z = 1);
    void dispatchIndirect(GLuint program, GLintptr offset);
    void requireParams() const;

    std::unique_ptr<gpu::ScanTexture> ownScan_;
    const gpu::ScanTexture* scan_;
    glm::ivec3 dims_;
    glm::vec3 sphereScale_; // model::sphereScale of the scan's spacing
    model::SolverOptions options_;
    std::unique_ptr<detail::SolverPrograms> programs_;
    std::unique_ptr<detail::GpuBrickPool> pool_;
    std::unique_ptr<detail::SpeedOnDemand> onDemand_; // built by the first on-demand speed
    model::LevelSetParams params_;
    speed::SpeedInputs speedInputs_;
    bool haveParams_ = false;
    std::uint32_t epoch_ = 1;
    model::SolverStats stats_;
    float lastTime_ = 0.0F;
    int lastIteration_ = 0;
    std::uint32_t lastUsed_ = 0;                // used slots at the last pool check
    std::optional<detail::ControlBlock> known_; // the GPU's control block, when known
    // The iteration the watches' checks count from: the first step after the last change
    // (noteChange), so a check falls every checkInterval iterations of the run however its calls
    // split it (a frame's few iterations) and the watches see the same intervals every time.
    std::optional<std::uint32_t> checkOrigin_;
    bool converged_ = false;
    bool settled_ = false; // SettleWatch at the last check
    bool wakePending_ = true;
    std::vector<model::Barrier> barriers_;
    std::optional<model::Box> box_;
    gpu::Texture claimed_; // solver/voxel_bits.hpp; empty: none claimed
    gpu::Texture kept_;    // the same; empty: none kept
    std::optional<model::Reach> reach_;
    LeakWatch leakWatch_;
    SettleWatch settleWatch_;
    RunawayWatch runawayWatch_;
    std::function<void(const FrontCheck&)> checkObserver_;
};

} // namespace steerseg::solver
