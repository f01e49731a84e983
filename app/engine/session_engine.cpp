#include "engine/session_engine.hpp"

#include "engine/view_setup.hpp"
#include "gpu/gl.hpp"
#include "gpu/gl_counts.hpp"
#include "model/speed_kind.hpp"
#include "render/slice_frame.hpp"
#include "scan/read_progress.hpp"
#include "scan/scan_reader.hpp"

#include <algorithm>
#include <stdexcept>

namespace steerseg::engine {

struct SessionEngine::PendingLoad {
    std::string path;
    std::future<void> done;
    scan::LoadedScan result;
    std::string error;
    std::uint64_t fileBytes = 0; // 0: unknown (a folder, the sample)
    std::atomic<std::uint64_t> bytesRead{0};
};

namespace {

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

} // namespace

std::string scanShortName(const std::string& path) {
    if (path == scan::kBuiltinSample) {
        return "sample";
    }
    std::filesystem::path p(path);
    while (!p.empty() && p.filename().empty() && p.parent_path() != p) {
        p = p.parent_path(); // "series/" names the folder ("/" has no name and is its own parent)
    }
    std::string name = p.filename().string();
    for (const char* ext : {".nii.gz", ".nii", ".nrrd", ".nhdr", ".mha", ".mhd", ".mgz", ".dcm"}) {
        if (endsWith(name, ext)) {
            name.resize(name.size() - std::string(ext).size());
            break;
        }
    }
    // The name ends up in export paths: keep it to characters every filesystem takes.
    for (char& c : name) {
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                           (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        if (!plain) {
            c = '_';
        }
    }
    return name.empty() ? "scan" : name;
}

SessionEngine::SessionEngine(model::SolverOptions options, EdgeSpeedRules edge,
                             std::size_t undoGpuBytes)
    : options_(options), edge_(edge), undoGpuBudget_(undoGpuBytes) {}

SessionEngine::~SessionEngine() {
    if (pending_) {
        abandoned_.push_back(std::move(pending_));
    }
    for (auto& load : abandoned_) {
        if (load->done.valid()) {
            load->done.wait();
        }
    }
}

void SessionEngine::beginLoad(const std::string& path) {
    if (pending_) {
        abandoned_.push_back(std::move(pending_));
    }
    // Those that finished meanwhile go now, with the scans they read: an operator tapping Load
    // again and again on a slow scan must not pile them up until the kiosk exits.
    std::erase_if(abandoned_, [](const std::unique_ptr<PendingLoad>& load) {
        return load->done.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    });
    auto load = std::make_unique<PendingLoad>();
    load->path = path;
    PendingLoad* raw = load.get();
    // The worker writes only into its own PendingLoad, which lives (in pending_ or abandoned_)
    // until the worker has been joined.
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
        load->fileBytes = std::filesystem::file_size(path, ec);
    }
    load->done = std::async(std::launch::async, [raw] {
        scan::countReadsInto(&raw->bytesRead);
        try {
            raw->result = scan::readScan(raw->path);
        } catch (const std::exception& e) {
            raw->error = e.what();
        } catch (...) {
            raw->error = raw->path + ": unknown error while reading";
        }
        scan::countReadsInto(nullptr);
    });
    pending_ = std::move(load);
}

workflow::LoadPoll SessionEngine::pollLoad() {
    workflow::LoadPoll poll;
    poll.progress = -1.0; // the readers do not report progress
    if (!pending_) {
        poll.kind = workflow::LoadPoll::Failed;
        poll.error = "no scan is being loaded";
        return poll;
    }
    if (pending_->done.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        if (pending_->fileBytes > 0) {
            // The file's bytes read so far; the upload to the GPU that follows is quick.
            poll.progress = std::min(0.99, static_cast<double>(pending_->bytesRead.load()) /
                                               static_cast<double>(pending_->fileBytes));
        }
        return poll;
    }
    pending_->done.get();
    std::unique_ptr<PendingLoad> load = std::move(pending_);
    if (!load->error.empty()) {
        poll.kind = workflow::LoadPoll::Failed;
        poll.error = load->error;
        return poll;
    }
    try {
        // The GPU upload: on this thread, which holds the context. The previous scan's session
        // goes first so two scans never share the GPU's memory.
        session_.reset();
        snapshots_.clear();
        undoGpuBytes_ = 0;
        untidyCopies_ = 0;
        lastProbe_.reset();
        pendingLimit_.reset();
        session_ = std::make_unique<session::Session>(std::move(load->result), options_);
    } catch (const std::exception& e) {
        session_.reset();
        poll.kind = workflow::LoadPoll::Failed;
        poll.error = load->path + ": " + e.what();
        return poll;
    }
    const Volume& scan = session_->scan();
    info_ = {};
    info_.identity = load->path + " (" + session_->format() + ")";
    scanPath_ = load->path;
    info_.name = scanShortName(load->path);
    info_.dims = scan.dims();
    info_.spacing = scan.geometry().spacing;
    info_.minValue = scan.stats().min;
    info_.maxValue = scan.stats().max;
    info_.units = session_->format() == "dicom" && scan.stats().min < -500.0 ? "HU" : "";
    // Which index axis each orientation pages along depends on how the scan is stored.
    for (const model::SliceAxis axis :
         {model::SliceAxis::Axial, model::SliceAxis::Coronal, model::SliceAxis::Sagittal}) {
        info_.sliceCount[static_cast<int>(axis)] =
            scan.dims()[render::sliceAxisFor(scan.geometry(), viewKindOf(axis))];
    }
    insideCounted_.reset();
    changed();
    ++attached_;
    poll.kind = workflow::LoadPoll::Ready;
    poll.progress = 1.0;
    return poll;
}

session::Session& SessionEngine::requireSession() const {
    if (!session_) {
        throw std::logic_error("no scan is loaded");
    }
    return *session_;
}

void SessionEngine::changed() {
    ++version_;
}

workflow::ScanInfo SessionEngine::scanInfo() const {
    return info_;
}

model::SolverOptions consoleSolverOptions() {
    model::SolverOptions options;
    options.stopOnLeak = true;
    return options;
}

void SessionEngine::addSeed(const model::Sphere& sphere) {
    const ScopedSeconds timed(work_.edit);
    requireSession().addSeed(sphere);
    changed();
    countThroughEdit();
}

void SessionEngine::erase(const model::Sphere& sphere) {
    const ScopedSeconds timed(work_.edit);
    requireSession().erase(sphere);
    changed();
    countThroughEdit();
}

// The solver counts the voxels a sphere edit moves across the surface, as it counts a step's
// (SolverStats::netGained), and every step call ends on a check: the count taken before plus
// what was counted since is the inside count after the edit, with no count of the pool (a read
// of every brick: 0.13-0.32 s of a correction's first visible change on a 256^3 scan).
void SessionEngine::countThroughEdit() {
    if (insideCounted_) {
        const std::int64_t net = session_->stats().netGained;
        *insideCounted_ += net - netAtCount_;
        netAtCount_ = net;
        volumeVersion_ = version_;
    }
}

bool SessionEngine::addBarrier(const model::Barrier& barrier) {
    const ScopedSeconds timed(work_.edit);
    if (barriers_.size() >= model::kMaxBarriers) {
        return false;
    }
    requireSession().holdBarrier(barrier); // its sphere is on its side already
    barriers_.push_back(barrier);
    changed();
    countThroughEdit(); // holding a sphere moves no voxel
    return true;
}

void SessionEngine::setReach(const std::optional<model::Reach>& reach) {
    if (reach || session_) {
        requireSession().setReach(reach);
    }
}

void SessionEngine::setBarriers(const std::vector<model::Barrier>& barriers) {
    session::Session& s = requireSession();
    s.clearBarriers();
    barriers_.clear();
    for (const model::Barrier& b : barriers) {
        s.holdBarrier(b); // the level set restored with them holds their spheres
        barriers_.push_back(b);
    }
    insideCounted_.reset();
}

void SessionEngine::clearLevelSet() {
    setBarriers({});
    requireSession().clearLevelSet();
    insideCounted_.reset();
    changed();
}

bool SessionEngine::hasLevelSet() const {
    // Once seeded, a level set stays on the GPU when an erase or a run takes every voxel out:
    // then there is no surface, as the exact count (after an edit or a stop) knows for free.
    if (!session_ || !session_->hasLevelSet()) {
        return false;
    }
    return !(insideCounted_ && volumeVersion_ == version_ && *insideCounted_ <= 0);
}

void SessionEngine::setParams(const model::LevelSetParams& params) {
    const ScopedSeconds timed(work_.speed);
    requireSession().setParams(params);
    changed(); // the speed view shows the parameters
}

session::SpeedSettings SessionEngine::edgeSettings() const {
    if (!lastProbe_) {
        throw std::invalid_argument("the edge speed needs a probe first: the noise in the probed "
                                    "tissue sets its smoothing and kappa");
    }
    const session::SpeedProbe p = session::probeSpeed(requireSession().scan(), *lastProbe_);
    session::SpeedSettings s;
    s.kind = model::SpeedKind::Edge;
    s.smoothing = {edge_.smoothIterations, static_cast<float>(edge_.conductanceFactor * p.noise)};
    s.kappa = static_cast<float>(edge_.kappaFactor * p.noise);
    return s;
}

void SessionEngine::setSpeed(const workflow::SpeedChoice& choice) {
    const ScopedSeconds timed(work_.speed);
    session::Session& s = requireSession();
    session::SpeedSettings settings;
    if (choice.kind == model::SpeedKind::Edge) {
        settings = edgeSettings();
    }
    settings.kind = choice.kind;
    // The classifier samples from the union of a class's spheres: taps and strokes alike.
    settings.inside = choice.inside;
    settings.inside.insert(settings.inside.end(), choice.paintedInside.begin(),
                           choice.paintedInside.end());
    settings.outside = choice.outside;
    settings.outside.insert(settings.outside.end(), choice.paintedOutside.begin(),
                            choice.paintedOutside.end());
    settings.withinWindow = choice.withinWindow;
    settings.placeReach = choice.placeReach;
    settings.box = choice.box;
    // Preprocessing and training run here, on the frame loop (a blocking step: docs/speed.md).
    s.setSpeed(settings);
    changed();
}

bool SessionEngine::fillSpeedAhead(double seconds) {
    // Asking with 0 bricks costs no GL work: whole speeds stop here every frame.
    if (!session_ || !(seconds > 0.0) || session_->evaluateSpeedAhead(0) == 0) {
        return false;
    }
    const auto start = std::chrono::steady_clock::now();
    session_->evaluateSpeedAhead(aheadBricks_);
    gpu::finish(); // the piece's cost sizes the next one
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double next = static_cast<double>(aheadBricks_) * seconds / std::max(spent, 1e-5);
    aheadBricks_ = static_cast<std::uint32_t>(std::clamp(next, 1.0, 4096.0));
    ++speedVersion_;
    return true;
}

model::StepResult SessionEngine::step(int iterations) {
    if (pendingLimit_) {
        const model::WithdrawLimit limit = *pendingLimit_;
        pendingLimit_.reset();
        keepBeyondLimit(limit);
    }
    const model::StepResult result = requireSession().step(iterations);
    // The frame loop times this call against its budget: the GPU's work belongs to it.
    gpu::finish();
    changed();
    return result;
}

model::SolverStats SessionEngine::stats() const {
    return session_ ? session_->stats() : model::SolverStats{};
}

double SessionEngine::volumeMl() const {
    if (!session_ || !session_->hasLevelSet()) {
        return 0.0;
    }
    if (!insideCounted_) {
        return exactVolumeMl();
    }
    // The steps' counts are taken at the pool checks: the figure lags the front by at most one
    // check's growth, and a count taken between checks may be off by that much until the next
    // exact one (a pause, an edit).
    return millilitres(*insideCounted_ + session_->stats().netGained - netAtCount_);
}

double SessionEngine::exactVolumeMl() const {
    if (!session_ || !session_->hasLevelSet()) {
        return 0.0;
    }
    if (insideCounted_ && volumeVersion_ == version_) {
        return millilitres(*insideCounted_);
    }
    const ScopedSeconds timed(work_.count);
    insideCounted_ = static_cast<std::int64_t>(session_->insideVoxels());
    netAtCount_ = session_->stats().netGained;
    volumeVersion_ = version_;
    return millilitres(*insideCounted_);
}

double SessionEngine::millilitres(std::int64_t voxels) const {
    const glm::dvec3 s = requireSession().scan().geometry().spacing;
    return static_cast<double>(std::max<std::int64_t>(voxels, 0)) * s.x * s.y * s.z / 1000.0;
}

std::vector<std::filesystem::path> SessionEngine::exportMask(const std::filesystem::path& path) {
    return requireSession().exportMask(path);
}

} // namespace steerseg::engine
