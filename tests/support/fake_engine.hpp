#pragma once

// An Engine in memory for the workflow's tests, the UI's and the kiosk's: deterministic, no GL.
// The scan is a small grid, the level set a voxel mask edited by the spheres; steps count
// iterations and converge after a fixed number without a change. Loads finish after a given
// number of polls; loads, exports, steps, edits and snapshots fail on demand. It counts live
// snapshots and every call the workflow should never make (misuse), so tests can assert both.
#include "workflow/engine.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::test {

class FakeEngine : public workflow::Engine {
  public:
    // 16 x 12 x 8 voxels of 1 x 1 x 2 mm, values -1000..1000 HU, named "fake".
    static workflow::ScanInfo defaultScan();
    explicit FakeEngine(workflow::ScanInfo scan = defaultScan());

    // --- what to do -------------------------------------------------------------------------
    int loadPolls = 2;               // pollLoad() calls answered Running before the outcome
    std::string loadError;           // non-empty: loads fail with it
    std::string exportError;         // non-empty: exportMask throws it
    std::string failExportsEndingIn; // non-empty: exportMask throws for a path ending so
    std::string stepError;           // non-empty: step throws it
    std::string editError;           // non-empty: addSeed and erase throw it
    std::string snapshotError;       // non-empty: snapshot throws it
    // Non-empty: setSpeed throws it for edge and classify (the threshold speed prepares
    // nothing, so nothing can fail; the kiosk's engine always accepts it).
    std::string speedError;
    double probeStddev = 10.0; // the spread every probe reports
    int convergeAfter = 40;    // iterations without an edit or new parameters until converged
    // Set: every step paints this sphere inside, as a front creeping there would (reach or not).
    std::optional<model::Sphere> stepGrows;
    // Set: the next step stops as the solver's leak watch stops it, there (once).
    std::optional<model::LeakSite> stepLeaks;
    bool writeExports = false; // exportMask writes a small file at the path

    // --- what happened ----------------------------------------------------------------------
    std::vector<std::string> loads;             // beginLoad's paths
    std::vector<std::filesystem::path> exports; // successful exports
    int setParamsCalls = 0;
    std::vector<workflow::SpeedChoice> speeds; // setSpeed's accepted choices, in order
    [[nodiscard]] model::SpeedKind speedKind() const { return speed_.kind; }
    [[nodiscard]] const model::LevelSetParams& params() const { return params_; }
    [[nodiscard]] std::size_t liveSnapshots() const { return snapshots_.size(); }
    [[nodiscard]] int misuse() const { return misuse_; }
    [[nodiscard]] const std::string& lastMisuse() const { return lastMisuse_; }
    [[nodiscard]] bool attached() const { return attached_; }
    [[nodiscard]] std::size_t insideVoxels() const { return inside_; }
    [[nodiscard]] bool inside(const glm::ivec3& voxel) const;

    // --- Engine ------------------------------------------------------------------------------
    void beginLoad(const std::string& path) override;
    workflow::LoadPoll pollLoad() override;
    [[nodiscard]] workflow::ScanInfo scanInfo() const override;
    [[nodiscard]] workflow::ProbeResult probe(const glm::dvec3& voxel,
                                              double radiusMm) const override;
    [[nodiscard]] workflow::ProbeResult measure(const glm::dvec3& voxel,
                                                double radiusMm) const override;
    // The fake's values along i (as measure's), the box's voxels in storage order.
    [[nodiscard]] std::vector<double> values(const model::Box& box,
                                             std::size_t most) const override;
    void addSeed(const model::Sphere& sphere) override;
    void erase(const model::Sphere& sphere) override;
    bool addBarrier(const model::Barrier& barrier) override;
    [[nodiscard]] int barriers() const override { return static_cast<int>(barriers_.size()); }
    [[nodiscard]] const std::vector<model::Barrier>& barrierList() const { return barriers_; }
    void setReach(const std::optional<model::Reach>& reach) override;
    [[nodiscard]] const std::optional<model::Reach>& reach() const { return reach_; }
    void limitWithdrawal(const std::optional<model::WithdrawLimit>& limit) override;
    [[nodiscard]] const std::optional<model::WithdrawLimit>& withdrawLimit() const {
        return withdrawLimit_;
    }
    void clearLevelSet() override;
    [[nodiscard]] bool hasLevelSet() const override { return inside_ > 0; }
    void setParams(const model::LevelSetParams& params) override;
    void setSpeed(const workflow::SpeedChoice& choice) override;
    model::StepResult step(int iterations) override;
    [[nodiscard]] model::SolverStats stats() const override;
    [[nodiscard]] double volumeMl() const override;
    workflow::SnapshotId snapshot() override;
    void restore(workflow::SnapshotId id) override;
    void drop(workflow::SnapshotId id) override;
    std::vector<std::filesystem::path> exportMask(const std::filesystem::path& path) override;
    [[nodiscard]] MaskRuns levelSetMask() const override;
    // The inside voxels counted; the lines from the mask's first and last inside voxel.
    [[nodiscard]] MaskMeasurements measureStructure(const MaskRuns* mask) const override;
    void setMask(const MaskRuns& mask) override;
    void setClaimed(const MaskRuns& claimed) override;
    std::vector<std::filesystem::path>
    exportStructures(const std::filesystem::path& path,
                     const std::vector<workflow::ExportedStructure>& structures) override;
    // Voxels another structure claims now (setClaimed).
    [[nodiscard]] std::size_t claimedVoxels() const;
    // The last exportStructures' structures: name, label and mask, in order.
    struct ExportedMask {
        std::string name;
        int label = 0;
        MaskRuns mask;
    };
    std::vector<ExportedMask> exportedStructures;

  private:
    struct LevelSet {
        std::vector<std::uint8_t> mask;
        std::size_t inside = 0;
        int iterations = 0;
        float time = 0.0F;
        std::vector<model::Barrier> barriers;
    };
    // Records a call the workflow should not have made, then throws it as std::logic_error.
    [[noreturn]] void misused(const std::string& what) const;
    void requireScan(const char* call) const;
    void paint(const model::Sphere& sphere, std::uint8_t value);
    void changed() { sinceChange_ = 0; }

    workflow::ScanInfo scan_;
    bool attached_ = false;
    bool loading_ = false;
    int polls_ = 0;
    std::vector<std::uint8_t> mask_;    // 1 inside, i fastest
    std::vector<std::uint8_t> claimed_; // setClaimed's; empty: none
    std::size_t inside_ = 0;
    int iterations_ = 0;
    float time_ = 0.0F;
    int sinceChange_ = 0;
    model::LevelSetParams params_;
    workflow::SpeedChoice speed_;
    std::vector<model::Barrier> barriers_;
    std::optional<model::Reach> reach_;
    std::optional<model::WithdrawLimit> withdrawLimit_;
    std::map<workflow::SnapshotId, LevelSet> snapshots_;
    workflow::SnapshotId nextId_ = 1;
    mutable int misuse_ = 0;
    mutable std::string lastMisuse_;
};

} // namespace steerseg::test
