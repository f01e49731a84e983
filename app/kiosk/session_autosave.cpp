#include "kiosk/session_autosave.hpp"

#include "engine/session_engine.hpp"
#include "workflow/param_ranges.hpp"
#include "workflow/transition_table.hpp"
#include "workflow/utc_time.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <ostream>

namespace steerseg::kiosk {

namespace {

using SteadyClock = std::chrono::steady_clock;

// Moments a session can be picked up from; an autosave of a finished one (exported) or of one
// that never had a scan offers nothing.
bool resumable(model::State state) {
    return state != model::State::NoScan && state != model::State::Loading &&
           state != model::State::Done;
}

// "2026-11-23 13:01:40 UTC": for the operator and the log.
std::string utcOf(std::int64_t ms) {
    std::string iso =
        workflow::isoUtc(std::chrono::system_clock::time_point(std::chrono::milliseconds(ms)));
    if (iso.size() >= 19) {
        iso = iso.substr(0, 10) + " " + iso.substr(11, 8) + " UTC";
    }
    return iso;
}

} // namespace

SessionAutosave::SessionAutosave(const config::AutosaveConfig& config,
                                 const std::filesystem::path& auditLog, ResumeChoice choice,
                                 std::ostream& err)
    : config_(config), auditLog_(auditLog), err_(err),
      store_(std::make_unique<autosave::AutosaveStore>(config.folder, config.keep)) {
    if (choice != ResumeChoice::No) {
        std::vector<std::string> problems;
        std::optional<autosave::AutosaveStore::Found> found = store_->newest(problems);
        for (const std::string& p : problems) {
            err_ << "steerseg kiosk: autosave: " << p << '\n';
        }
        if (found && !found->clean && resumable(found->snapshot.state)) {
            const autosave::ScanReference& saved = found->snapshot.scan;
            if (const std::string diff =
                    autosave::differenceBetween(saved, autosave::referenceOf(saved.path));
                !diff.empty()) {
                err_ << "steerseg kiosk: autosave: " << found->file.string()
                     << " not offered: " << diff << '\n';
            } else {
                offer_ = std::move(found);
                err_ << "steerseg kiosk: autosave: an unfinished session can be resumed: "
                     << offerText() << " (" << offer_->file.string() << ")\n";
                readAuditLogBeforeItOpens();
            }
        }
        if (choice == ResumeChoice::Yes) {
            if (offer_) {
                resuming_ = true;
            } else {
                err_ << "steerseg kiosk: autosave: --resume: no unfinished session to resume\n";
            }
        }
    }
    writer_ = std::make_unique<autosave::AutosaveWriter>(*store_);
}

SessionAutosave::~SessionAutosave() = default;

std::string SessionAutosave::offerText() const {
    if (!offer_) {
        return {};
    }
    const autosave::AutosaveSnapshot& s = offer_->snapshot;
    return engine::scanShortName(s.scan.path) + ", " + std::string(model::stateName(s.state)) +
           ", " + std::to_string(s.seeds) + (s.seeds == 1 ? " seed" : " seeds") + ", saved " +
           utcOf(s.savedAtMs);
}

void SessionAutosave::answer(bool resume) {
    if (!offering()) {
        return;
    }
    if (!resume) {
        err_ << "steerseg kiosk: autosave: discarded the unfinished session\n";
        offer_.reset();
        return;
    }
    resuming_ = true;
}

void SessionAutosave::frame(workflow::Workflow& flow, engine::SessionEngine& engine,
                            std::vector<model::Action>& actions) {
    reportWriteError();
    if (resuming_) {
        if (!loadQueued_) {
            for (const std::string& line : auditNotes_) {
                err_ << "steerseg kiosk: " << line << '\n';
            }
            scansAtResume_ = engine.scansAttached();
            actions.emplace_back(model::LoadScan{offer_->snapshot.scan.path});
            loadQueued_ = true;
            return;
        }
        finishResume(flow, engine);
        return;
    }
    const workflow::Status& status = flow.status();
    if (offering() && status.state != model::State::NoScan &&
        status.state != model::State::Loading && status.state != model::State::Inspect) {
        // The operator went on with new work without answering: that is a discard.
        answer(false);
    }
    if (!offering() && due(flow, engine)) {
        save(flow, engine);
    }
}

void SessionAutosave::finishResume(workflow::Workflow& flow, engine::SessionEngine& engine) {
    if (flow.state() == model::State::Loading) {
        return;
    }
    const autosave::AutosaveSnapshot& s = offer_->snapshot;
    std::string failure;
    if (engine.scansAttached() == scansAtResume_ || flow.state() != model::State::Inspect) {
        failure = flow.status().message.empty() ? "its scan did not load" : flow.status().message;
    } else if (engine.scanInfo().dims != s.dims) {
        failure = "the scan's grid differs from the autosave's";
    } else {
        try {
            engine.setMask(s.mask);
            workflow::RestoredSession restored{s.params,
                                               s.seeds,
                                               s.erasures,
                                               s.state,
                                               "resumed the session saved " + utcOf(s.savedAtMs),
                                               s.barriers,
                                               s.structures};
            const workflow::Workflow::Outcome o = flow.restoreSession(restored);
            if (!o.accepted) {
                failure = o.reason;
            }
        } catch (const std::exception& e) {
            failure = e.what();
        }
    }
    if (failure.empty()) {
        err_ << "steerseg kiosk: autosave: resumed " << offer_->file.string() << " (saved "
             << utcOf(s.savedAtMs) << ", " << model::stateName(s.state) << ") as "
             << model::stateName(flow.state()) << '\n';
    } else {
        err_ << "steerseg kiosk: autosave: resume of " << offer_->file.string()
             << " failed: " << failure << '\n';
    }
    resuming_ = false;
    offer_.reset();
    if (failure.empty()) {
        save(flow, engine); // the restored point is this session's first autosave
    }
}

bool SessionAutosave::due(const workflow::Workflow& flow,
                          const engine::SessionEngine& engine) const {
    using model::State;
    const workflow::Status& status = flow.status();
    const State state = status.state;
    if (state == State::NoScan || state == State::Loading || state == State::Exporting) {
        return false;
    }
    if (!savedState_ || *savedState_ != state) {
        return true;
    }
    if (state == State::Evolving) {
        return std::chrono::duration<double>(SteadyClock::now() - savedAt_).count() >=
               config_.intervalSeconds;
    }
    const model::LevelSetParams& p = status.params;
    return engine.levelSetVersion() != savedVersion_ || p.T != savedParams_.T ||
           p.eps != savedParams_.eps || p.alpha != savedParams_.alpha ||
           status.radius != savedRadius_ || status.box != savedBox_ ||
           flow.structuresVersion() != savedStructures_;
}

void SessionAutosave::save(const workflow::Workflow& flow, engine::SessionEngine& engine) {
    const workflow::Status& status = flow.status();
    const SteadyClock::time_point start = SteadyClock::now();
    if (engine.scansAttached() != referenceScans_) {
        // A stat (a DICOM folder's listing) once per scan, not once per snapshot.
        scanReference_ = autosave::referenceOf(engine.scanPath());
        referenceScans_ = engine.scansAttached();
    }
    autosave::AutosaveSnapshot s;
    s.scan = scanReference_;
    s.dims = status.scan.dims;
    s.savedAtMs = std::chrono::duration_cast<std::chrono::milliseconds>(
                      std::chrono::system_clock::now().time_since_epoch())
                      .count();
    s.state = status.state;
    s.params.values[workflow::indexOf(model::Param::T)] = static_cast<double>(status.params.T);
    s.params.values[workflow::indexOf(model::Param::Eps)] = static_cast<double>(status.params.eps);
    s.params.values[workflow::indexOf(model::Param::Alpha)] =
        static_cast<double>(status.params.alpha);
    s.params.values[workflow::indexOf(model::Param::Radius)] = status.radius;
    s.params.preset = status.preset;
    s.params.speed = {status.speed, status.insideExamples, status.outsideExamples,
                      status.paintedInside, status.paintedOutside};
    s.params.speed.box = status.box;
    // While classify waits, the speed that runs is the one it falls back to; once it runs, what
    // it fell back to is not shown and the threshold speed stands in.
    s.params.fallback = status.speedInForce != model::SpeedKind::Classify
                            ? status.speedInForce
                            : model::SpeedKind::Threshold;
    s.seeds = status.seeds;
    s.erasures = status.erasures;
    s.iterations = status.iterations;
    s.evolvedTime = status.evolvedTime;
    s.barriers = engine.barrierList();
    if (status.hasLevelSet && engine.session() != nullptr) {
        const std::vector<std::uint8_t> mask = engine.session()->mask();
        readBackSeconds_ += std::chrono::duration<double>(SteadyClock::now() - start).count();
        s.mask = encodeRuns(mask);
    }
    // A session of one structure as the scan started it saves as before structures; with more,
    // every other structure's mask (already runs in host memory) rides along.
    if (status.structures.size() > 1 ||
        (!status.structures.empty() &&
         status.structures.front().info.name != model::kFirstStructureName)) {
        s.structures = flow.structures();
    }
    writer_->submit(std::move(s));
    savedStructures_ = flow.structuresVersion();
    savedState_ = status.state;
    savedVersion_ = engine.levelSetVersion();
    savedParams_ = status.params;
    savedBox_ = status.box;
    savedRadius_ = status.radius;
    savedAt_ = start;
    const double seconds = std::chrono::duration<double>(SteadyClock::now() - start).count();
    ++snapshots_;
    captureSeconds_ += seconds;
    captureMaxSeconds_ = std::max(captureMaxSeconds_, seconds);
}

void SessionAutosave::readAuditLogBeforeItOpens() {
    // A resumed session goes on writing the same log: what the crash left of it, read before
    // the log reopens (which starts a fresh line after a torn one).
    try {
        const workflow::AuditLogContents log = workflow::readAuditLog(auditLog_);
        auditNotes_.push_back("resuming: audit log " + auditLog_.string() + " continues after " +
                              std::to_string(log.records.size()) + " records");
        if (log.torn) {
            auditNotes_.push_back("audit log: torn last record from the crash, " + *log.torn);
        }
        for (const std::string& p : log.problems) {
            auditNotes_.push_back("audit log: skipped " + p);
        }
    } catch (const std::exception& e) {
        auditNotes_.emplace_back(e.what());
    }
}

void SessionAutosave::reportWriteError() {
    if (const auto error = writer_->takeError()) {
        err_ << "steerseg kiosk: " << *error << '\n';
    }
}

void SessionAutosave::finish(const workflow::Workflow& flow, engine::SessionEngine& engine) {
    if (!offering() && !resuming_) {
        const workflow::Status& status = flow.status();
        if (due(flow, engine)) {
            save(flow, engine);
        }
        const bool unexported =
            workflow::factsOf(status).result && status.state != model::State::Done;
        if (!unexported) {
            writer_->markClean();
        }
    }
    writer_->flush();
    reportWriteError();
    if (snapshots_ > 0) {
        err_ << "steerseg kiosk: autosave: " << snapshots_ << " snapshots in "
             << config_.folder.string() << "; on the frame thread "
             << 1e3 * captureSeconds_ / snapshots_ << " ms on average (mask read-back "
             << 1e3 * readBackSeconds_ / snapshots_ << " ms), " << 1e3 * captureMaxSeconds_
             << " ms at most\n";
    }
}

} // namespace steerseg::kiosk
