#pragma once

// The workflow's engine on the real thing: scans read by io on a worker thread, then the
// session (scan texture, solver, renderer) built on the frame loop's thread, which owns the GL
// context. Level-set snapshots for undo are copies in GPU memory (session::LevelSetCopy) up to
// a budget, beyond which the oldest become masks in host memory.
#include "core/mask_runs.hpp"
#include "engine/work_seconds.hpp"
#include "session/session.hpp"
#include "session/speed_probe.hpp"
#include "workflow/engine.hpp"

#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace steerseg::engine {

// How the kiosk sets the edge speed's smoothing and kappa: from the noise of the last probe, as
// the command line's --probe does (session::probeSpeed), scaled by the config's [speed] factors.
struct EdgeSpeedRules {
    int smoothIterations = 5;
    double conductanceFactor = session::kConductanceFactor; // K = factor * the probe's noise
    double kappaFactor = session::kKappaFactor;             // kappa = factor * the probe's noise
};

// The solver as the console runs it: a leak stops the front (the workflow pauses and says
// where); everything else as SolverOptions' defaults.
model::SolverOptions consoleSolverOptions();

// GPU memory undo's copies may hold. Each copies the brick pool, so it follows the surface, not
// the scan: a 256^3 scan whose pool held every brick would copy 66 MB, MNI152's white matter
// after its first run copies ~12 MB (2 of them per correction). Beyond it the oldest copies move
// to host memory as masks (what every snapshot was before, ~70 ms each there), so a long session
// on a large scan cannot fill the GPU through undo.
inline constexpr std::size_t kUndoGpuBytes = std::size_t{256} << 20U;

class SessionEngine final : public workflow::Engine {
  public:
    explicit SessionEngine(model::SolverOptions options = {}, EdgeSpeedRules edge = {},
                           std::size_t undoGpuBytes = kUndoGpuBytes);
    ~SessionEngine() override;
    SessionEngine(const SessionEngine&) = delete;
    SessionEngine& operator=(const SessionEngine&) = delete;

    void beginLoad(const std::string& path) override;
    workflow::LoadPoll pollLoad() override;
    [[nodiscard]] workflow::ScanInfo scanInfo() const override;
    [[nodiscard]] workflow::ProbeResult probe(const glm::dvec3& voxel,
                                              double radiusMm) const override;
    [[nodiscard]] workflow::ProbeResult measure(const glm::dvec3& voxel,
                                                double radiusMm) const override;
    [[nodiscard]] std::vector<double> values(const model::Box& box,
                                             std::size_t most) const override;
    void addSeed(const model::Sphere& sphere) override;
    void erase(const model::Sphere& sphere) override;
    bool addBarrier(const model::Barrier& barrier) override;
    [[nodiscard]] int barriers() const override { return static_cast<int>(barriers_.size()); }
    [[nodiscard]] const std::vector<model::Barrier>& barrierList() const { return barriers_; }
    void setReach(const std::optional<model::Reach>& reach) override;
    void limitWithdrawal(const std::optional<model::WithdrawLimit>& limit) override;
    void clearLevelSet() override;
    [[nodiscard]] bool hasLevelSet() const override;
    void setParams(const model::LevelSetParams& params) override;
    void setSpeed(const workflow::SpeedChoice& choice) override;
    model::StepResult step(int iterations) override;
    [[nodiscard]] model::SolverStats stats() const override;
    [[nodiscard]] double volumeMl() const override;
    [[nodiscard]] double exactVolumeMl() const override;
    workflow::SnapshotId snapshot() override;
    void restore(workflow::SnapshotId id) override;
    void drop(workflow::SnapshotId id) override;
    std::vector<std::filesystem::path> exportMask(const std::filesystem::path& path) override;
    // session_engine_structures.cpp
    [[nodiscard]] MaskRuns levelSetMask() const override;
    [[nodiscard]] MaskMeasurements measureStructure(const MaskRuns* mask) const override;
    void setClaimed(const MaskRuns& claimed) override;
    std::vector<std::filesystem::path>
    exportStructures(const std::filesystem::path& path,
                     const std::vector<workflow::ExportedStructure>& structures) override;

    // Resume, and a structure the operator comes back to: the level set from a mask (no runs:
    // none), without barriers. std::invalid_argument for a mask of another size.
    void setMask(const MaskRuns& mask) override;
    // The path the attached scan was loaded from ("" before one is).
    [[nodiscard]] const std::string& scanPath() const { return scanPath_; }

    // The session, once a scan is attached (the kiosk draws through it).
    [[nodiscard]] session::Session* session() { return session_.get(); }
    // Counts every change of the level set (edits, steps, restores): the views redraw on it.
    [[nodiscard]] std::uint64_t levelSetVersion() const { return version_; }
    // Counts the scans attached so far: what was drawn of an earlier one is stale.
    [[nodiscard]] std::uint64_t scansAttached() const { return attached_; }
    // The classify speed is evaluated where the front goes; for the speed view, the rest of
    // the scan is filled in a piece per frame, each sized to take about `seconds` (from the
    // last piece's cost). Returns whether a piece was filled; speedVersion() counts them.
    bool fillSpeedAhead(double seconds);
    [[nodiscard]] std::uint64_t speedVersion() const { return speedVersion_; }
    [[nodiscard]] const WorkSeconds& workSeconds() const { return work_; }
    // GPU memory undo's copies hold now and snapshots kept as masks. At most the budget, but
    // for an edit's two newest copies until keepUndoWithinBudget: a snapshot leaves the older
    // copies' move to host memory to the frame after the edit it belongs to.
    [[nodiscard]] std::size_t undoGpuBytes() const { return undoGpuBytes_; }
    [[nodiscard]] std::size_t undoMasks() const;
    void keepUndoWithinBudget();

  private:
    session::Session& requireSession() const;
    void changed();

    struct PendingLoad;
    [[nodiscard]] session::SpeedSettings edgeSettings() const;

    model::SolverOptions options_;
    EdgeSpeedRules edge_;
    std::unique_ptr<session::Session> session_;
    // The last probe (voxels): the edge speed's noise comes from it. A probe changes no level
    // set and is const to the workflow; remembering where it was is this engine's business.
    mutable std::optional<model::Sphere> lastProbe_;
    workflow::ScanInfo info_;
    std::string scanPath_;
    std::unique_ptr<PendingLoad> pending_;
    // Loads replaced before they finished: a read cannot be interrupted, so they are joined on
    // destruction instead of detached with the scan they are writing into.
    std::vector<std::unique_ptr<PendingLoad>> abandoned_;
    // A level set as undo keeps it: its copy in GPU memory, or once moved out of the budget
    // its mask (no copy and empty runs: none), and the barriers in force.
    struct Snapshot {
        std::optional<session::LevelSetCopy> copy;
        MaskRuns mask;
        std::vector<model::Barrier> barriers;
    };
    void setBarriers(const std::vector<model::Barrier>& barriers);
    void putMask(const MaskRuns& mask);
    void countThroughEdit();
    std::size_t undoGpuBudget_;
    std::size_t undoGpuBytes_ = 0;
    // The copies taken since the last keepUndoWithinBudget, which may stand above the budget.
    static constexpr int kUntidyCopies = 2;
    int untidyCopies_ = 0;
    std::map<workflow::SnapshotId, Snapshot> snapshots_;
    std::vector<model::Barrier> barriers_; // as the solver holds them
    // limitWithdrawal's, until the next step keeps the voxels beyond it (keepBeyondLimit).
    std::optional<model::WithdrawLimit> pendingLimit_;
    void keepBeyondLimit(const model::WithdrawLimit& limit);
    workflow::SnapshotId nextSnapshot_ = 1;
    std::uint64_t version_ = 0;
    std::uint64_t attached_ = 0;
    std::uint64_t speedVersion_ = 0;
    std::uint32_t aheadBricks_ = 1; // the next piece of fillSpeedAhead
    mutable WorkSeconds work_;
    // The volume: the inside voxels counted on the pool read back from the GPU (when asked for
    // the exact figure after a run or a new level set; Session::insideVoxels), and while the
    // front moves, and after a sphere edit, that count plus the voxels the steps and the edits
    // moved across the surface since (SolverStats::netGained): a run reads no mask back, which on
    // a 512x512x120 scan cost llvmpipe a frame twice a second.
    mutable std::optional<std::int64_t> insideCounted_;
    mutable std::int64_t netAtCount_ = 0;     // SolverStats::netGained when it was counted
    mutable std::uint64_t volumeVersion_ = 0; // the level set's version it was counted on
    [[nodiscard]] double millilitres(std::int64_t voxels) const;
};

// "CT_sarcoma" from ".../CT_sarcoma.nii.gz", "sample" from "builtin:sample", the folder's
// name for a DICOM series: what export names and the panel use.
std::string scanShortName(const std::string& path);

} // namespace steerseg::engine
