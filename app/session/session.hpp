#pragma once

// One operator session on one scan: the scan, its texture on the GPU, the solver and the
// renderer, behind the operations the command line and the kiosk's workflow call. The public
// header names no GL type and no device: callers hold a current GLES 3.1 context (made by
// platform/) for the session's whole life, and speak in voxel indices and real units.
#include "core/rgba_image.hpp"
#include "core/volume.hpp"
#include "exports/export_writer.hpp"
#include "exports/structure_export.hpp"
#include "model/level_set_params.hpp"
#include "model/solver_types.hpp"
#include "render/render_params.hpp"
#include "render/slice_frame.hpp"
#include "render/structure_surface.hpp"
#include "scan/scan_reader.hpp"
#include "session/probe.hpp"
#include "session/speed_settings.hpp"
#include "solver/level_set_copy.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace steerseg::session {

// How long to evolve: a number of iterations, until an evolved time, or until converged (with
// `iterations` the cap for the last two).
struct RunMode {
    enum Kind { Iterations, Time, Converge } kind = Iterations;
    int iterations = 0;
    float time = 0.0F;
};

// The GL calls of a run (gpu/gl_counts): what an iteration costs whatever the GPU (issue 50).
struct RunCalls {
    std::uint64_t dispatches = 0;
    std::uint64_t barriers = 0;
    std::uint64_t readBacks = 0; // the host waiting for buffers the GPU wrote
    std::uint64_t finishes = 0;
};

struct RunOutcome {
    model::StepResult result;
    double solveSeconds = 0.0; // solver only, GPU work finished
    RunCalls calls;            // the solver's, without the finish that ends the timing
};

// The level set copied in GPU memory for undo (Session::copyLevelSet, solver::LevelSetCopy).
struct LevelSetCopy {
    solver::LevelSetCopy levelSet;
    bool hasLevelSet = false;
};

class Session {
  public:
    // Reads a scan (a file, a DICOM folder or "builtin:sample"; scan::readScan's errors).
    static Session open(const std::filesystem::path& path,
                        const model::SolverOptions& options = {});
    Session(Volume scan, std::string format, const model::SolverOptions& options = {});
    // A scan as read, keeping its DICOM source (if any) for DICOM SEG export.
    explicit Session(scan::LoadedScan scan, const model::SolverOptions& options = {});
    ~Session();
    Session(Session&&) noexcept;
    Session& operator=(Session&&) noexcept;

    [[nodiscard]] const Volume& scan() const;
    [[nodiscard]] const std::string& format() const; // "nifti", "dicom", "builtin", ...

    // Seeds grow the level set, erasers cut it; voxel-index centre, radius in voxels along the
    // finest axis, round in mm (model::Sphere). A sphere
    // whose centre is outside the scan or whose radius is not a positive finite number is
    // refused (std::invalid_argument naming the problem).
    void addSeed(const model::Sphere& sphere);
    void erase(const model::Sphere& sphere);
    // A barrier: an erase that stays a no-go region for the rest of the run (a leak's neck).
    // At most model::kMaxBarriers; std::invalid_argument beyond.
    void addBarrier(const model::Barrier& barrier);
    // A barrier whose sphere is on its side already (solver::LevelSetSolver::holdBarrier).
    void holdBarrier(const model::Barrier& barrier);
    void clearBarriers();
    // Where the surface may move (solver::LevelSetSolver::setReach); nullopt: everywhere.
    void setReach(const std::optional<model::Reach>& reach);
    // Voxels other structures hold (non-zero = claimed, one byte per voxel of the scan, i
    // fastest): the surface never enters them (solver::LevelSetSolver::setClaimed); an empty
    // span clears it. std::invalid_argument for a span of another size. Stays until set again.
    void setClaimed(std::span<const std::uint8_t> claimed);
    [[nodiscard]] bool hasClaimed() const;
    // Voxels the surface never leaves (solver::LevelSetSolver::setKept), the same way; an empty
    // span clears them.
    void setKept(std::span<const std::uint8_t> kept);
    // A mask on the scan's grid (inside where > 0.5) replaces the level set. Throws
    // std::runtime_error naming the file when it cannot be read or its grid differs.
    void startFromMask(const std::filesystem::path& mask);
    // Replaces the level set with `inside` (non-zero = inside, i fastest, one byte per voxel of
    // the scan): undo and resume go back to a mask they kept. Its phi is rounded off between
    // the voxels (solver::smoothMaskPhi: drawn smooth, the same voxels inside). All zero
    // leaves no level set.
    // std::invalid_argument for a mask of the wrong size.
    void setMask(std::span<const std::uint8_t> inside);
    void clearLevelSet();
    [[nodiscard]] bool hasLevelSet() const;
    // Undo's copies: a few buffer copies on the GPU each way; restoreLevelSet gives back
    // exactly the level set copied (barriers and reach stay as they are now), maskOf reads a
    // copy back as mask() reads the level set. std::invalid_argument for another scan's copy.
    [[nodiscard]] LevelSetCopy copyLevelSet() const;
    void restoreLevelSet(const LevelSetCopy& copy);
    [[nodiscard]] std::vector<std::uint8_t> maskOf(const LevelSetCopy& copy) const;

    // Validated (std::invalid_argument); may change between any two steps.
    void setParams(const model::LevelSetParams& params);
    // The speed that drives the surface (docs/speed.md): smooths the scan (once per smoothing
    // parameters: a change of kind or kappa alone reuses it), computes the edge factor, trains
    // the classifier. Restarts the convergence clock like setParams. std::invalid_argument for
    // settings validateSpeedSettings refuses; std::runtime_error when the GPU cannot hold the
    // textures, and for classify until the voxel classifier is built in. T and eps stay in
    // setParams. Settings equal to those in force but for the box only move the box
    // (LevelSetSolver::setBox). Default: the threshold speed on the raw scan.
    void setSpeed(const SpeedSettings& settings, const SpeedProgress& progress = {});
    [[nodiscard]] const SpeedSettings& speed() const;
    [[nodiscard]] const SpeedTiming& speedTiming() const;
    // The classify speed is evaluated where the front goes (docs/speed.md); these compute it
    // further, for a view of the speed: up to maxBricks more bricks (returns how many remain,
    // 0 once complete, and at once for the other speeds; 0 bricks only asks), or the rest of
    // the scan. speedBricksEvaluated() reads back how many bricks hold it (for reports).
    std::uint32_t evaluateSpeedAhead(std::uint32_t maxBricks);
    void completeSpeed();
    [[nodiscard]] std::uint32_t speedBricksEvaluated() const;
    model::StepResult step(int iterations);
    RunOutcome run(const RunMode& mode);
    [[nodiscard]] bool converged() const;
    [[nodiscard]] model::SolverStats stats() const;
    [[nodiscard]] const model::SolverOptions& options() const;

    // 1 inside, i fastest; reads the level set back from the GPU.
    [[nodiscard]] std::vector<std::uint8_t> mask() const;
    // The voxels inside, counted without reading the whole level set back.
    [[nodiscard]] std::uint64_t insideVoxels() const;
    // The level set, phi < 0 inside, in voxel units, i fastest; read back from the GPU.
    [[nodiscard]] std::vector<float> phi() const;
    // The segmentation as `format` (exports::writeExport): voxel formats from the mask on the
    // scan's grid, surfaces (STL, PLY) from the level set's zero crossing. Throws
    // files::WriteError.
    exports::ExportSummary exportAs(const std::filesystem::path& path, model::ExportFormat format,
                                    const exports::SegmentInfo& segment = {}) const;
    // exportAs in the format the file's extension names (model::exportFormatFor); the files
    // written, `path` first (a DICOM SEG's measurement report after it).
    std::vector<std::filesystem::path> exportMask(const std::filesystem::path& path) const;
    // Several structures in the format the file's extension names (exports::writeStructures):
    // `layers` carry their masks, but for the one at `levelSet` (if any), which is this
    // session's level set, its mask and phi read back here. The files written, `path` first.
    std::vector<std::filesystem::path> exportStructures(const std::filesystem::path& path,
                                                        std::vector<exports::StructureLayer> layers,
                                                        std::optional<std::size_t> levelSet) const;

    // Presets for this scan (MR-style transfer function, anterior camera, middle slice).
    [[nodiscard]] render::ViewParams defaultView(render::ViewKind kind,
                                                 const glm::ivec2& size) const;
    // Draws one view of the scan and the level set (if any); slice views return their frame.
    std::optional<render::SliceFrame> render(const render::ViewParams& params);
    // The other structures the 3D view draws beside the level set (render::Renderer::
    // setStructures: uploaded when `version` differs from the one last given, which
    // structuresVersion() returns).
    void setStructures(std::span<const render::StructureSurface> structures, std::uint64_t version);
    [[nodiscard]] std::optional<std::uint64_t> structuresVersion() const;
    // Waits for the GPU's queued work (a caller timing its draws against a frame budget).
    void finishGpuWork() const;
    // The last view drawn.
    [[nodiscard]] RgbaImage picture() const;
    // Picture `index` (ViewParams::target) as a GL texture name and its size, for a screen that
    // composes the views itself (the kiosk); 0 and 0x0 before anything was drawn into it.
    [[nodiscard]] unsigned int pictureTexture(int index) const;
    [[nodiscard]] glm::ivec2 pictureSize(int index) const;

    // Intensity statistics around a voxel-index point (the probe of any view).
    [[nodiscard]] ProbeStats probeAt(const glm::dvec3& index, double radiusMm,
                                     Stray stray = Stray::LeaveOut) const;

  private:
    struct Gpu;
    Volume scan_;
    std::string format_;
    std::shared_ptr<const scan::DicomSource> dicom_; // null unless read from DICOM
    model::SolverOptions options_;
    std::unique_ptr<Gpu> gpu_;
    bool hasLevelSet_ = false;
};

} // namespace steerseg::session
