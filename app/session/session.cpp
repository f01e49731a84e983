#include "session/session.hpp"

#include "core/mask_inside.hpp"
#include "exports/export_writer.hpp"
#include "gpu/gl_counts.hpp"
#include "render/renderer.hpp"
#include "scan/scan_reader.hpp"
#include "session/session_gpu.hpp"
#include "solver/level_set_solver.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <utility>

namespace steerseg::session {

namespace {

// Bricks per dispatch when completing the speed: within the 65535 groups of one dispatch, and
// a bounded piece of work for a GPU watchdog.
constexpr std::uint32_t kAheadBricksPerCall = 4096;

} // namespace

Session Session::open(const std::filesystem::path& path, const model::SolverOptions& options) {
    return Session(scan::readScan(path), options);
}

Session::Session(scan::LoadedScan scan, const model::SolverOptions& options)
    : Session(std::move(scan.volume), std::move(scan.format), options) {
    dicom_ = std::move(scan.dicom);
}

Session::Session(Volume scan, std::string format, const model::SolverOptions& options)
    : scan_(std::move(scan)), format_(std::move(format)), options_(options),
      gpu_(std::make_unique<Gpu>(scan_, options_)) {}

Session::~Session() = default;
Session::Session(Session&&) noexcept = default;
Session& Session::operator=(Session&&) noexcept = default;

const Volume& Session::scan() const {
    return scan_;
}

const std::string& Session::format() const {
    return format_;
}

void Session::addSeed(const model::Sphere& sphere) {
    gpu_->solver.addSphere(sphere);
    hasLevelSet_ = true;
}

void Session::erase(const model::Sphere& sphere) {
    gpu_->solver.removeSphere(sphere);
}

void Session::addBarrier(const model::Barrier& barrier) {
    gpu_->solver.addBarrier(barrier);
}

void Session::holdBarrier(const model::Barrier& barrier) {
    gpu_->solver.holdBarrier(barrier);
}

void Session::clearBarriers() {
    gpu_->solver.clearBarriers();
}

void Session::setReach(const std::optional<model::Reach>& reach) {
    gpu_->solver.setReach(reach);
}

void Session::setClaimed(std::span<const std::uint8_t> claimed) {
    gpu_->solver.setClaimed(claimed);
}

void Session::setKept(std::span<const std::uint8_t> kept) {
    gpu_->solver.setKept(kept);
}

bool Session::hasClaimed() const {
    return gpu_->solver.hasClaimed();
}

void Session::startFromMask(const std::filesystem::path& path) {
    const scan::LoadedScan mask = scan::readScan(path);
    if (mask.volume.dims() != scan_.dims()) {
        throw std::runtime_error(path.string() + ": mask is " + dimsText(mask.volume.dims()) +
                                 " but the scan is " + dimsText(scan_.dims()));
    }
    try {
        setMask(maskInside(mask.volume));
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path.string() + ": " + e.what());
    }
}

void Session::setMask(std::span<const std::uint8_t> inside) {
    if (inside.size() != scan_.geometry().voxelCount()) {
        throw std::invalid_argument("mask has " + std::to_string(inside.size()) +
                                    " voxels but the scan " +
                                    std::to_string(scan_.geometry().voxelCount()));
    }
    gpu_->solver.initFromSmoothMask(inside);
    hasLevelSet_ = std::any_of(inside.begin(), inside.end(), [](std::uint8_t v) { return v != 0; });
}

void Session::clearLevelSet() {
    const std::vector<std::uint8_t> none(scan_.geometry().voxelCount(), 0);
    setMask(none);
}

bool Session::hasLevelSet() const {
    return hasLevelSet_;
}

LevelSetCopy Session::copyLevelSet() const {
    return {gpu_->solver.copyLevelSet(), hasLevelSet_};
}

void Session::restoreLevelSet(const LevelSetCopy& copy) {
    gpu_->solver.restoreLevelSet(copy.levelSet);
    hasLevelSet_ = copy.hasLevelSet;
}

std::vector<std::uint8_t> Session::maskOf(const LevelSetCopy& copy) const {
    return gpu_->solver.readMask(copy.levelSet);
}

void Session::setParams(const model::LevelSetParams& params) {
    gpu_->solver.setParams(params);
}

std::uint32_t Session::evaluateSpeedAhead(std::uint32_t maxBricks) {
    return gpu_->solver.evaluateSpeedAhead(maxBricks);
}

std::uint32_t Session::speedBricksEvaluated() const {
    return gpu_->solver.speedBricksEvaluated();
}

void Session::completeSpeed() {
    while (evaluateSpeedAhead(kAheadBricksPerCall) > 0) {
    }
}

const SpeedSettings& Session::speed() const {
    return gpu_->speed;
}

const SpeedTiming& Session::speedTiming() const {
    return gpu_->timing;
}

model::StepResult Session::step(int iterations) {
    return gpu_->solver.step(iterations);
}

RunOutcome Session::run(const RunMode& mode) {
    const auto start = std::chrono::steady_clock::now();
    const gpu::GlCounts before = gpu::glCounts();
    RunOutcome out;
    switch (mode.kind) {
    case RunMode::Iterations:
        out.result = gpu_->solver.step(mode.iterations);
        break;
    case RunMode::Time:
        out.result = gpu_->solver.evolveUntil(mode.time, mode.iterations);
        break;
    case RunMode::Converge:
        out.result = gpu_->solver.runUntilConverged(mode.iterations);
        break;
    }
    const gpu::GlCounts calls = gpu::glCounts() - before;
    out.calls = {calls.dispatches, calls.barriers, calls.readBacks, calls.finishes};
    gpu::finish(); // the solver's time includes its GPU work, not the caller's next readback
    out.solveSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

bool Session::converged() const {
    return gpu_->solver.converged();
}

model::SolverStats Session::stats() const {
    return gpu_->solver.stats();
}

const model::SolverOptions& Session::options() const {
    return options_;
}

std::vector<std::uint8_t> Session::mask() const {
    return gpu_->solver.readMask();
}

std::uint64_t Session::insideVoxels() const {
    return gpu_->solver.countInside();
}

std::vector<float> Session::phi() const {
    return gpu_->solver.readPhi();
}

exports::ExportSummary Session::exportAs(const std::filesystem::path& path,
                                         model::ExportFormat format,
                                         const exports::SegmentInfo& segment) const {
    const std::vector<std::uint8_t> inside = mask();
    std::vector<float> field;
    if (model::isSurfaceFormat(format)) {
        field = phi();
    }
    return exports::writeExport(path, format,
                                {scan_.geometry(), inside, field, segment, dicom_.get(), &scan_});
}

std::vector<std::filesystem::path> Session::exportMask(const std::filesystem::path& path) const {
    const auto format = model::exportFormatOfFile(path);
    if (!format) {
        throw files::WriteError(path, "cannot tell the export format from the name (" +
                                          model::exportFormatNames() + ")");
    }
    std::vector<std::filesystem::path> written{path};
    for (const std::filesystem::path& companion : exportAs(path, *format).companions) {
        written.push_back(companion);
    }
    return written;
}

std::vector<std::filesystem::path>
Session::exportStructures(const std::filesystem::path& path,
                          std::vector<exports::StructureLayer> layers,
                          std::optional<std::size_t> levelSet) const {
    const auto format = model::exportFormatOfFile(path);
    if (!format) {
        throw files::WriteError(path, "cannot tell the export format from the name (" +
                                          model::exportFormatNames() + ")");
    }
    std::vector<std::uint8_t> inside;
    std::vector<float> field;
    if (levelSet && *levelSet < layers.size()) {
        inside = mask();
        layers[*levelSet].mask = inside;
        if (model::isSurfaceFormat(*format)) {
            field = phi();
            layers[*levelSet].phi = field;
        }
    }
    const exports::ExportSummary summary = exports::writeStructures(
        path, *format, {scan_.geometry(), std::move(layers), dicom_.get(), &scan_});
    std::vector<std::filesystem::path> written{path};
    written.insert(written.end(), summary.companions.begin(), summary.companions.end());
    return written;
}

render::ViewParams Session::defaultView(render::ViewKind kind, const glm::ivec2& size) const {
    return gpu_->renderer.defaultParams(kind, size);
}

std::optional<render::SliceFrame> Session::render(const render::ViewParams& params) {
    // The speed view shows the solver's own data term: what moves the front.
    const speed::SpeedInputs& speed = gpu_->solver.speedInputs();
    if (!hasLevelSet_) {
        return gpu_->renderer.render(params, nullptr, speed);
    }
    const solver::BrickPoolView pool = gpu_->solver.poolView();
    return gpu_->renderer.render(params, &pool, speed);
}

void Session::setStructures(std::span<const render::StructureSurface> structures,
                            std::uint64_t version) {
    gpu_->renderer.setStructures(structures, version);
}

std::optional<std::uint64_t> Session::structuresVersion() const {
    return gpu_->renderer.structuresVersion();
}

RgbaImage Session::picture() const {
    return gpu_->renderer.readback();
}

void Session::finishGpuWork() const {
    gpu::finish();
}

unsigned int Session::pictureTexture(int index) const {
    return gpu_->renderer.target(index).texture();
}

glm::ivec2 Session::pictureSize(int index) const {
    return gpu_->renderer.target(index).size();
}

ProbeStats Session::probeAt(const glm::dvec3& index, double radiusMm, Stray stray) const {
    return probe(scan_, index, radiusMm, stray);
}

} // namespace steerseg::session
