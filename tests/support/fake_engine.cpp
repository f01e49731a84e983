#include "support/fake_engine.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace steerseg::test {

workflow::ScanInfo FakeEngine::defaultScan() {
    workflow::ScanInfo s;
    s.identity = "fake:scan";
    s.name = "fake";
    s.dims = {16, 12, 8};
    s.spacing = {1.0, 1.0, 2.0};
    s.minValue = -1000.0;
    s.maxValue = 1000.0;
    s.units = "HU";
    return s;
}

FakeEngine::FakeEngine(workflow::ScanInfo scan) : scan_(std::move(scan)) {}

void FakeEngine::misused(const std::string& what) const {
    ++misuse_;
    lastMisuse_ = what;
    throw std::logic_error("fake engine misused: " + what);
}

void FakeEngine::requireScan(const char* call) const {
    if (!attached_) {
        misused(std::string(call) + " without a scan");
    }
}

bool FakeEngine::inside(const glm::ivec3& v) const {
    const glm::ivec3 d = scan_.dims;
    if (!attached_ || glm::any(glm::lessThan(v, glm::ivec3(0))) ||
        glm::any(glm::greaterThanEqual(v, d))) {
        return false;
    }
    return mask_[static_cast<std::size_t>(v.x + d.x * (v.y + d.y * v.z))] != 0;
}

void FakeEngine::beginLoad(const std::string& path) {
    loads.push_back(path);
    // Like the kiosk's engine, the old scan is gone once a new one is asked for.
    attached_ = false;
    loading_ = true;
    polls_ = 0;
    mask_.clear();
    inside_ = 0;
    iterations_ = 0;
    time_ = 0.0F;
}

workflow::LoadPoll FakeEngine::pollLoad() {
    workflow::LoadPoll p;
    if (!loading_) {
        misused("pollLoad without a load");
    }
    if (polls_ < loadPolls) {
        ++polls_;
        p.progress = static_cast<double>(polls_) / static_cast<double>(loadPolls + 1);
        return p;
    }
    loading_ = false;
    if (!loadError.empty()) {
        p.kind = workflow::LoadPoll::Failed;
        p.error = loadError;
        return p;
    }
    attached_ = true;
    mask_.assign(static_cast<std::size_t>(scan_.dims.x) * static_cast<std::size_t>(scan_.dims.y) *
                     static_cast<std::size_t>(scan_.dims.z),
                 0);
    inside_ = 0;
    iterations_ = 0;
    time_ = 0.0F;
    speed_ = {}; // a new scan starts with the paper's speed, as the session does
    changed();
    p.kind = workflow::LoadPoll::Ready;
    p.progress = 1.0;
    return p;
}

workflow::ScanInfo FakeEngine::scanInfo() const {
    requireScan("scanInfo");
    return scan_;
}

workflow::ProbeResult FakeEngine::probe(const glm::dvec3& voxel, double radiusMm) const {
    return measure(voxel, radiusMm);
}

workflow::ProbeResult FakeEngine::measure(const glm::dvec3& voxel, double radiusMm) const {
    requireScan("measure");
    if (!std::isfinite(voxel.x) || !std::isfinite(voxel.y) || !std::isfinite(voxel.z) ||
        !std::isfinite(radiusMm) || radiusMm <= 0.0) {
        misused("measure with a non-finite position or a radius <= 0");
    }
    // Voxels whose centres lie within the radius (mm), as session::probe counts them; the
    // mean rises along i so different probes give different targets.
    const glm::dvec3 reach = radiusMm / scan_.spacing;
    const glm::dvec3 lo = glm::max(glm::ceil(voxel - reach), glm::dvec3(0.0));
    const glm::dvec3 hi = glm::min(glm::floor(voxel + reach), glm::dvec3(scan_.dims - 1));
    workflow::ProbeResult r;
    for (double k = lo.z; k <= hi.z; ++k) {
        for (double j = lo.y; j <= hi.y; ++j) {
            for (double i = lo.x; i <= hi.x; ++i) {
                const glm::dvec3 d = (glm::dvec3(i, j, k) - voxel) * scan_.spacing;
                if (glm::dot(d, d) <= radiusMm * radiusMm) {
                    ++r.count;
                }
            }
        }
    }
    if (r.count > 0) {
        const double along = std::clamp(voxel.x / std::max(1, scan_.dims.x - 1), 0.0, 1.0);
        r.mean = scan_.minValue + (scan_.maxValue - scan_.minValue) * along;
        r.stddev = probeStddev;
    }
    return r;
}

std::vector<double> FakeEngine::values(const model::Box& box, std::size_t most) const {
    requireScan("values");
    try {
        model::validateBox(box, scan_.dims);
    } catch (const std::invalid_argument& e) {
        misused(std::string("values of a box that does not fit: ") + e.what());
    }
    std::vector<double> out;
    for (int k = box.lo.z; k <= box.hi.z; ++k) {
        for (int j = box.lo.y; j <= box.hi.y; ++j) {
            for (int i = box.lo.x; i <= box.hi.x && out.size() < most; ++i) {
                out.push_back(scan_.minValue + (scan_.maxValue - scan_.minValue) *
                                                   static_cast<double>(i) /
                                                   std::max(1, scan_.dims.x - 1));
            }
        }
    }
    return out;
}

void FakeEngine::paint(const model::Sphere& s, std::uint8_t value) {
    requireScan(value != 0 ? "addSeed" : "erase");
    const glm::ivec3 d = scan_.dims;
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(s.centre[a]) || s.centre[a] < 0.0F ||
            s.centre[a] > static_cast<float>(d[a] - 1)) {
            misused("a sphere centred outside the scan");
        }
    }
    if (!std::isfinite(s.radius) || s.radius <= 0.0F) {
        misused("a sphere with a radius <= 0");
    }
    if (!editError.empty()) {
        throw std::runtime_error(editError);
    }
    // Round in mm, as the real solver's spheres are (model::Sphere).
    const glm::vec3 scale = model::sphereScale(scan_.spacing);
    const auto [lo, hi] = model::sphereVoxelBox(s, scale, d);
    for (int k = lo.z; k <= hi.z; ++k) {
        for (int j = lo.y; j <= hi.y; ++j) {
            for (int i = lo.x; i <= hi.x; ++i) {
                if (!model::sphereHolds(s, glm::dvec3(i, j, k), scale)) {
                    continue;
                }
                const auto at = static_cast<std::size_t>(i + d.x * (j + d.y * k));
                std::uint8_t& m = mask_[at];
                // Another structure's voxel stays outside, as the solver's claimed barrier keeps
                // the surface out of it.
                if (value != 0 && !claimed_.empty() && claimed_[at] != 0) {
                    continue;
                }
                if (m != value) {
                    inside_ = value != 0 ? inside_ + 1 : inside_ - 1;
                    m = value;
                }
            }
        }
    }
    if (inside_ == 0) {
        iterations_ = 0;
        time_ = 0.0F;
    }
    changed();
}

void FakeEngine::addSeed(const model::Sphere& sphere) {
    paint(sphere, 1);
}

void FakeEngine::erase(const model::Sphere& sphere) {
    paint(sphere, 0);
}

void FakeEngine::setReach(const std::optional<model::Reach>& reach) {
    if (reach) {
        requireScan("setReach");
    }
    reach_ = reach;
}

void FakeEngine::limitWithdrawal(const std::optional<model::WithdrawLimit>& limit) {
    if (limit) {
        requireScan("limitWithdrawal");
        if (!(limit->depthMm >= 0.0) || !std::isfinite(limit->depthMm)) {
            misused("limitWithdrawal with a depth that is negative or not finite");
        }
    }
    withdrawLimit_ = limit;
}

bool FakeEngine::addBarrier(const model::Barrier& barrier) {
    requireScan("addBarrier");
    if (barriers_.size() >= model::kMaxBarriers) {
        return false;
    }
    barriers_.push_back(barrier);
    return true;
}

void FakeEngine::clearLevelSet() {
    requireScan("clearLevelSet");
    barriers_.clear();
    std::fill(mask_.begin(), mask_.end(), std::uint8_t{0});
    inside_ = 0;
    iterations_ = 0;
    time_ = 0.0F;
    changed();
}

void FakeEngine::setParams(const model::LevelSetParams& p) {
    requireScan("setParams");
    // The solver's own checks (validateParams), which the workflow's clamping must satisfy.
    if (!std::isfinite(p.T) || !std::isfinite(p.eps) || !std::isfinite(p.alpha) || p.eps < 0.0F ||
        p.alpha < 0.0F || p.alpha > 1.0F) {
        misused("setParams with invalid values");
    }
    ++setParamsCalls;
    params_ = p;
    changed();
}

void FakeEngine::setSpeed(const workflow::SpeedChoice& choice) {
    requireScan("setSpeed");
    const bool classify = choice.kind == model::SpeedKind::Classify;
    if (classify && (!choice.hasInside() || !choice.hasOutside())) {
        misused("setSpeed classify without an example of each kind");
    }
    if (!classify && (choice.hasInside() || choice.hasOutside())) {
        misused("setSpeed with examples for a speed that learns nothing");
    }
    for (const auto* list :
         {&choice.inside, &choice.outside, &choice.paintedInside, &choice.paintedOutside}) {
        for (const model::Sphere& s : *list) {
            for (int a = 0; a < 3; ++a) {
                if (!std::isfinite(s.centre[a]) || s.centre[a] < 0.0F ||
                    s.centre[a] > static_cast<float>(scan_.dims[a] - 1)) {
                    misused("an example centred outside the scan");
                }
            }
            if (!std::isfinite(s.radius) || s.radius <= 0.0F) {
                misused("an example with a radius <= 0");
            }
        }
    }
    if (!speedError.empty() && choice.kind != model::SpeedKind::Threshold) {
        throw std::runtime_error(speedError);
    }
    speeds.push_back(choice);
    speed_ = choice;
    changed();
}

model::StepResult FakeEngine::step(int iterations) {
    requireScan("step");
    if (inside_ == 0) {
        misused("step without a level set");
    }
    if (iterations <= 0) {
        misused("step with no iterations");
    }
    if (!stepError.empty()) {
        throw std::runtime_error(stepError);
    }
    if (stepGrows) {
        paint(*stepGrows, 1);
    }
    iterations_ += iterations;
    sinceChange_ += iterations;
    time_ += 0.25F * static_cast<float>(iterations);
    model::StepResult r;
    r.iterations = iterations;
    r.evolvedTime = time_;
    r.converged = sinceChange_ >= convergeAfter;
    r.stopReason = model::StopReason::IterationLimit;
    if (stepLeaks) {
        r.stopReason = model::StopReason::Leak;
        r.leak = std::exchange(stepLeaks, std::nullopt);
    }
    return r;
}

model::SolverStats FakeEngine::stats() const {
    model::SolverStats s;
    s.iterations = iterations_;
    s.evolvedTime = time_;
    return s;
}

double FakeEngine::volumeMl() const {
    return static_cast<double>(inside_) * scan_.spacing.x * scan_.spacing.y * scan_.spacing.z /
           1000.0;
}

workflow::SnapshotId FakeEngine::snapshot() {
    requireScan("snapshot");
    if (!snapshotError.empty()) {
        throw std::runtime_error(snapshotError);
    }
    const workflow::SnapshotId id = nextId_++;
    snapshots_[id] = LevelSet{mask_, inside_, iterations_, time_, barriers_};
    return id;
}

void FakeEngine::restore(workflow::SnapshotId id) {
    requireScan("restore");
    const auto it = snapshots_.find(id);
    if (it == snapshots_.end()) {
        misused("restore of snapshot " + std::to_string(id) + ", which is not live");
    }
    mask_ = it->second.mask;
    inside_ = it->second.inside;
    iterations_ = it->second.iterations;
    time_ = it->second.time;
    barriers_ = it->second.barriers;
    changed();
}

void FakeEngine::drop(workflow::SnapshotId id) {
    if (snapshots_.erase(id) == 0) {
        misused("drop of snapshot " + std::to_string(id) + ", which is not live");
    }
}

std::vector<std::filesystem::path> FakeEngine::exportMask(const std::filesystem::path& path) {
    requireScan("exportMask");
    if (inside_ == 0) {
        misused("exportMask without a level set");
    }
    if (!exportError.empty()) {
        throw std::runtime_error(exportError);
    }
    const std::string name = path.string();
    if (!failExportsEndingIn.empty() && name.size() >= failExportsEndingIn.size() &&
        name.compare(name.size() - failExportsEndingIn.size(), failExportsEndingIn.size(),
                     failExportsEndingIn) == 0) {
        throw std::runtime_error(name + ": the disk is full: 100 bytes could not be written");
    }
    if (writeExports) {
        std::ofstream out(path);
        out << "fake mask " << inside_ << " voxels\n";
        if (!out) {
            throw std::runtime_error(path.string() + ": cannot write");
        }
    }
    exports.push_back(path);
    return {path};
}

MaskRuns FakeEngine::levelSetMask() const {
    requireScan("levelSetMask");
    return inside_ == 0 ? MaskRuns{} : encodeRuns(mask_);
}

MaskMeasurements FakeEngine::measureStructure(const MaskRuns* mask) const {
    requireScan("measureStructure");
    const std::vector<std::uint8_t> inside = mask != nullptr ? decodeRuns(*mask) : mask_;
    MaskMeasurements m;
    const glm::ivec3 d = scan_.dims;
    bool first = true;
    for (std::size_t v = 0; v < inside.size(); ++v) {
        if (inside[v] == 0) {
            continue;
        }
        const glm::dvec3 at(static_cast<double>(v % static_cast<std::size_t>(d.x)),
                            static_cast<double>((v / static_cast<std::size_t>(d.x)) %
                                                static_cast<std::size_t>(d.y)),
                            static_cast<double>(v / static_cast<std::size_t>(d.x * d.y)));
        if (first) {
            m.axial.longest.index[0] = at;
            m.axial.slice = static_cast<int>(at.z);
            first = false;
        }
        m.axial.longest.index[1] = at;
        ++m.voxels;
    }
    if (m.voxels == 0) {
        throw std::invalid_argument("no voxel is inside");
    }
    m.volumeMl = static_cast<double>(m.voxels) * scan_.spacing.x * scan_.spacing.y *
                 scan_.spacing.z / 1000.0;
    return m;
}

void FakeEngine::setMask(const MaskRuns& mask) {
    requireScan("setMask");
    barriers_.clear();
    if (mask.runs.empty()) {
        std::fill(mask_.begin(), mask_.end(), std::uint8_t{0});
    } else {
        if (mask.voxels != mask_.size()) {
            throw std::invalid_argument("a mask of another size");
        }
        mask_ = decodeRuns(mask);
    }
    inside_ = static_cast<std::size_t>(std::count(mask_.begin(), mask_.end(), std::uint8_t{1}));
    iterations_ = 0;
    time_ = 0.0F;
    changed();
}

void FakeEngine::setClaimed(const MaskRuns& claimed) {
    requireScan("setClaimed");
    if (claimed.runs.empty()) {
        claimed_.clear();
        return;
    }
    if (claimed.voxels != mask_.size()) {
        misused("setClaimed with a mask of another size");
    }
    claimed_ = decodeRuns(claimed);
}

std::size_t FakeEngine::claimedVoxels() const {
    return static_cast<std::size_t>(
        std::count_if(claimed_.begin(), claimed_.end(), [](std::uint8_t v) { return v != 0; }));
}

std::vector<std::filesystem::path>
FakeEngine::exportStructures(const std::filesystem::path& path,
                             const std::vector<workflow::ExportedStructure>& structures) {
    requireScan("exportStructures");
    if (structures.empty()) {
        misused("exportStructures without a structure");
    }
    if (!exportError.empty()) {
        throw std::runtime_error(exportError);
    }
    exportedStructures.clear();
    for (const workflow::ExportedStructure& s : structures) {
        const MaskRuns mask = s.mask != nullptr ? *s.mask : levelSetMask();
        if (mask.runs.empty()) {
            misused("exportStructures with an empty structure");
        }
        exportedStructures.push_back({s.info.name, s.label, mask});
    }
    exports.push_back(path);
    return {path};
}

} // namespace steerseg::test
