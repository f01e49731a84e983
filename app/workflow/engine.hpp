#pragma once

// What the workflow needs from the scan, the solver and the writers, and nothing more. The
// kiosk implements it over session::Session (GL, on the frame loop's thread); tests implement
// it in memory. Errors are exceptions with one line for the operator (std::exception::what()).
#include "core/mask_measurements.hpp"
#include "core/mask_runs.hpp"
#include "model/box.hpp"
#include "model/level_set_params.hpp" // plain structs only: the workflow links no solver code
#include "model/solver_types.hpp"
#include "model/speed_kind.hpp" // the enum only: the workflow links no speed code
#include "model/structure.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::workflow {

struct ScanInfo {
    std::string identity; // what the audit log names: the path and, for DICOM, the series UID
    std::string name;     // short, for file names and the panel ("CT_sarcoma", "sample")
    glm::ivec3 dims{0};
    glm::dvec3 spacing{1.0}; // mm
    // Slices per SliceAxis (axial, coronal, sagittal), which depends on the scan's orientation
    // (render::sliceAxisFor); 0: taken from dims as (k, j, i).
    glm::ivec3 sliceCount{0};
    double minValue = 0.0; // real units, the whole scan
    double maxValue = 0.0;
    std::string units; // "HU", "" ...
};

struct LoadPoll {
    enum Kind { Running, Ready, Failed } kind = Running;
    double progress = 0.0; // 0..1 when known, < 0 when not
    std::string error;     // Failed: the reader's message
};

struct ProbeResult {
    double mean = 0.0;
    double stddev = 0.0;
    std::size_t count = 0;   // voxels counted; 0: the sphere missed the scan
    std::size_t leftOut = 0; // a probe's stray voxel left out of mean and spread (0 or 1)
};

// The data term the engine should run (docs/speed.md). Threshold and Edge read T, eps and alpha
// (setParams); Classify reads alpha and is trained on the examples, spheres in voxels: inside
// from the operator's probes, outside from the outside marks, and the dabs of painted strokes
// (model::PaintStroke) and the spheres of corrections while steering (docs/steering.md), every
// one of which counts where taps count only as the newest kMaxExamples. The classifier samples
// its training voxels from the union of a class's spheres.
// The workflow passes examples only to Classify, and only when it has both kinds.
struct SpeedChoice {
    model::SpeedKind kind = model::SpeedKind::Threshold;
    std::vector<model::Sphere> inside;
    std::vector<model::Sphere> outside;
    // `= {}`: a choice written as {kind, inside, outside} (the tapped examples only) stays valid.
    std::vector<model::Sphere> paintedInside = {}; // at most kMaxPaintedExamples, oldest first
    std::vector<model::Sphere> paintedOutside = {};
    // Classify only: bounded by the window T +- eps (Settings::classifyWithinWindow).
    bool withinWindow = false;
    // Classify only: how far, in its radii, an example decides where appearance is unsure
    // (Settings::classifyPlaceReach).
    double placeReach = 0.0;
    // Every kind: the operator's box, which the surface does not leave (model::Box).
    std::optional<model::Box> box = std::nullopt;
    bool operator==(const SpeedChoice&) const = default;
    [[nodiscard]] bool hasInside() const { return !inside.empty() || !paintedInside.empty(); }
    [[nodiscard]] bool hasOutside() const { return !outside.empty() || !paintedOutside.empty(); }
};
// Dabs and corrections kept per class: a long session's strokes stay bounded in memory (and in
// every undo entry's copy of the parameters); the classifier samples voxels from them anyway.
inline constexpr std::size_t kMaxPaintedExamples = 4096;

// One structure of an export of several (Engine::exportStructures), in label order.
struct ExportedStructure {
    model::StructureInfo info;
    int label = 1;                  // its value in a label map, its segment number in a SEG
    const MaskRuns* mask = nullptr; // null: the engine's level set (the active structure)
};

// A copy of the level set that undo can go back to.
using SnapshotId = std::uint64_t;

class Engine {
  public:
    virtual ~Engine() = default;

    // Starts reading a scan off the frame loop; pollLoad() on later frames says how it goes.
    // A second beginLoad replaces the first.
    virtual void beginLoad(const std::string& path) = 0;
    // Ready: the scan is attached (GPU upload done on the caller's thread), the level set empty.
    virtual LoadPoll pollLoad() = 0;
    [[nodiscard]] virtual ScanInfo scanInfo() const = 0;

    // The scan's values in a sphere (mm) that becomes the probe: the edge speed measures its
    // noise there.
    [[nodiscard]] virtual ProbeResult probe(const glm::dvec3& voxel, double radiusMm) const = 0;
    // The same measure, leaving the probe where it was.
    [[nodiscard]] virtual ProbeResult measure(const glm::dvec3& voxel, double radiusMm) const = 0;
    // The scan's values (real units) in a box that fits the scan, at most `most` of them on an
    // even stride through it: what a box says about the tissue in it (workflow/box_tissue).
    [[nodiscard]] virtual std::vector<double> values(const model::Box& box,
                                                     std::size_t most) const = 0;

    // Sphere edits; std::invalid_argument for a sphere outside the scan.
    virtual void addSeed(const model::Sphere& sphere) = 0;
    virtual void erase(const model::Sphere& sphere) = 0;
    // A sphere held on its side for the rest of the run, so that a correction sticks (an erase
    // blocks, an added seed keeps): part of the level set's state, kept by snapshots and
    // cleared with it. The sphere is on its side already (the caller painted it, or restored a
    // level set that holds it): holding it paints nothing. False when the engine holds its most
    // (model::kMaxBarriers) already: the edit stands, without it.
    virtual bool addBarrier(const model::Barrier& barrier) = 0;
    [[nodiscard]] virtual int barriers() const = 0;
    // Where the next steps may move the surface: a correction's neighbourhood, or nullopt for
    // everywhere. Not part of the level set's state: the workflow sets it for a correction's
    // run and clears it when the run stops. std::invalid_argument for a sphere the scan
    // cannot hold.
    virtual void setReach(const std::optional<model::Reach>& reach) = 0;
    // How far the next steps may take the surface back beyond a sphere (model::WithdrawLimit),
    // measured from the surface the next step starts from; nullopt: as far as the speed says.
    // Not part of the level set's state, as the reach is not. std::invalid_argument for a
    // sphere the scan cannot hold or a depth that is negative or not finite.
    virtual void limitWithdrawal(const std::optional<model::WithdrawLimit>& limit) = 0;
    virtual void clearLevelSet() = 0;
    // A level set with a voxel inside, as far as known without counting: after an edit or an
    // exact count of a stop, an empty one is none; while a run moves, that is its stop's to say.
    [[nodiscard]] virtual bool hasLevelSet() const = 0;

    virtual void setParams(const model::LevelSetParams& params) = 0;
    // Switches the data term; may take a while (smoothing, the edge factor, training run
    // inside it). Throws with one line when it cannot (the previous speed stays in force).
    virtual void setSpeed(const SpeedChoice& choice) = 0;
    virtual model::StepResult step(int iterations) = 0;
    [[nodiscard]] virtual model::SolverStats stats() const = 0;
    // Segmented volume in millilitres (counted on the GPU side's mask). While the solver runs
    // it may be up to a fraction of a second old (counting reads the level set back);
    // exactVolumeMl() is the volume now, for a run that stopped and for the record.
    [[nodiscard]] virtual double volumeMl() const = 0;
    [[nodiscard]] virtual double exactVolumeMl() const { return volumeMl(); }

    // The level set as a mask (no runs: none): a structure the operator leaves is kept so.
    [[nodiscard]] virtual MaskRuns levelSetMask() const = 0;
    // A mask replaces the level set (no runs: none), without barriers: a structure the operator
    // comes back to. std::invalid_argument for a mask of another size.
    virtual void setMask(const MaskRuns& mask) = 0;
    // A structure's measurements on the scan (core/mask_measurements): `mask`, or the level set
    // when null. std::invalid_argument for an empty one.
    [[nodiscard]] virtual MaskMeasurements measureStructure(const MaskRuns* mask) const = 0;
    // Voxels the surface never enters (no runs: none): the other structures', which act as
    // barriers. Not part of the level set's state: it stays until set again.
    virtual void setClaimed(const MaskRuns& claimed) = 0;

    // Level-set copies for undo; restore keeps the snapshot, drop frees it.
    virtual SnapshotId snapshot() = 0;
    virtual void restore(SnapshotId id) = 0;
    virtual void drop(SnapshotId id) = 0;

    // Writes the mask on the scan's grid; std::runtime_error naming the path on failure. Returns
    // the files written, `path` first, then any written beside it (a DICOM SEG's measurement
    // report), so that the export's record and the DICOM node see them all.
    virtual std::vector<std::filesystem::path> exportMask(const std::filesystem::path& path) = 0;
    // The same for several structures at once, each its own segment, label or mesh
    // (exports/structure_export); the files written, `path` first.
    virtual std::vector<std::filesystem::path>
    exportStructures(const std::filesystem::path& path,
                     const std::vector<ExportedStructure>& structures) = 0;
};

} // namespace steerseg::workflow
