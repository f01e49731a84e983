#include "kiosk/kiosk_dicom_node.hpp"

#include "kiosk/dicom_node_config.hpp"
#include "kiosk/kiosk_pacs.hpp"
#include "net/dcmtk_quiet.hpp"
#include "net/outbox.hpp"
#include "net/received_series.hpp"
#include "net/store_scp.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::kiosk {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLogPrefix = "steerseg kiosk: dicom: ";
constexpr auto kPassInterval = std::chrono::seconds(1);
// Short enough that a peer gone silent does not hold a SIGTERM for long (systemd waits 90 s).
constexpr int kSendTimeoutSeconds = 10;

std::string waitingLine(const net::OutboxEntry& e) {
    std::string line = e.source.filename().string() + " to " + e.peer;
    if (e.attempts == 0) {
        return line + ": queued";
    }
    const auto wait =
        std::chrono::duration<double>(e.nextAttempt - std::chrono::system_clock::now());
    return line + ": waiting, attempt " + std::to_string(e.attempts) + " failed (" + e.lastProblem +
           "); next in " +
           std::to_string(static_cast<int>(std::ceil(std::max(0.0, wait.count())))) + " s";
}

} // namespace

struct DicomNode::Link {
    std::unique_ptr<net::Outbox> outbox;
    std::unique_ptr<net::StorageScp> scp;
    std::unique_ptr<PacsClient> pacs; // with a peer to query only
};

DicomNode::DicomNode(const config::DicomConfig& dicom)
    : dicom_(dicom), link_(std::make_unique<Link>()) {
    if (!dicom_.enabled) {
        return;
    }
    peers_ = sendPeerNames(dicom_);
    net::quietDcmtk(); // before the threads: DCMTK's loggers are process-wide
    // Bound here, before any thread reads DICOM (StorageScp::open).
    try {
        if (scpSettings(dicom_).allowed.empty()) {
            // A port nobody may call is only a port open: a site that sends only, sends.
            throw net::ScpError("no [[dicom.peers]] with receive = true");
        }
        link_->scp =
            std::make_unique<net::StorageScp>(scpSettings(dicom_), [this](const std::string& line) {
                // One line per object would bury the journal: a series is told once, when complete.
                if (!line.starts_with("stored ")) {
                    say(line);
                }
            });
        link_->scp->open();
        say("listening as " + dicom_.aet + " on port " + std::to_string(dicom_.port) +
            (dicom_.tlsReceive ? " (TLS)" : "") + ", storing into " + dicom_.store.string());
        scpThread_ = std::thread([this] { link_->scp->serve(stop_); });
    } catch (const std::exception& e) {
        // The kiosk goes on: the operator can still load folders and export to files.
        say(std::string("not receiving: ") + e.what());
    }
    try {
        link_->outbox = std::make_unique<net::Outbox>(dicom_.outbox, outboxBackoff(dicom_));
        // Listed before the first frame: a script's wait for an empty outbox must not take the
        // moment before the worker's first pass for a delivery (after a restart, say).
        publishPending(*link_->outbox, 0);
    } catch (const std::exception& e) {
        say(std::string("no outbox: ") + e.what());
    }
    if (std::any_of(dicom_.peers.begin(), dicom_.peers.end(),
                    [](const config::DicomPeerConfig& p) { return p.query; })) {
        link_->pacs = std::make_unique<PacsClient>(dicom_, link_->scp != nullptr);
    }
    worker_ = std::thread([this] { work(); });
}

DicomNode::~DicomNode() {
    stop();
}

void DicomNode::stop() {
    if (link_->pacs) {
        link_->pacs->stop();
    }
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (scpThread_.joinable()) {
        scpThread_.join();
    }
    if (worker_.joinable()) {
        worker_.join();
    }
}

void DicomNode::say(const std::string& line) {
    const std::lock_guard lock(mutex_);
    shared_.log.push_back(line);
}

void DicomNode::work() {
    net::Outbox* outbox = link_->outbox.get();
    std::vector<fs::path> complete;
    for (bool first = true; !stop_; first = false) {
        if (outbox) {
            queueExports(*outbox);
        }
        listStore(complete, first);
        if (outbox) {
            drain(*outbox);
        }
        std::unique_lock lock(mutex_);
        wake_.wait_for(lock, kPassInterval, [this] { return stop_ || !shared_.toQueue.empty(); });
    }
    // An export made just before the stop is queued still (a local copy, no network): the
    // next start sends it.
    if (outbox) {
        queueExports(*outbox);
    }
}

void DicomNode::queueExports(net::Outbox& outbox) {
    std::vector<fs::path> files;
    {
        const std::lock_guard lock(mutex_);
        files = shared_.toQueue;
    }
    if (files.empty()) {
        return;
    }
    for (const fs::path& file : files) {
        for (const std::string& peer : peers_) {
            try {
                say("queued " + file.string() + " for " + peer + " as " +
                    outbox.enqueue(file, peer));
            } catch (const std::exception& e) {
                // The export itself is on disk; only its sending is lost, and said so.
                say("cannot queue " + file.string() + " for " + peer + ": " + e.what());
            }
        }
    }
    publishPending(outbox, files.size());
}

// The outbox's entries for the panel; the first `handedOver` exports leave the hand-over list
// in the same moment, so that what waits is never missing from the list (a script waiting
// for an empty outbox would take the gap for a delivery).
void DicomNode::publishPending(const net::Outbox& outbox, std::size_t handedOver) {
    std::vector<std::string> problems;
    std::vector<std::string> lines;
    for (const net::OutboxEntry& e : outbox.pending(&problems)) {
        lines.push_back(waitingLine(e));
    }
    for (const std::string& p : problems) {
        lines.push_back("cannot be sent: " + p);
    }
    const std::lock_guard lock(mutex_);
    shared_.outbox = std::move(lines);
    shared_.toQueue.erase(shared_.toQueue.begin(),
                          shared_.toQueue.begin() + static_cast<std::ptrdiff_t>(handedOver));
}

// `complete`: the series seen complete so far; a new one is announced, except on the first
// pass (what the store held before the kiosk started is no news).
void DicomNode::listStore(std::vector<fs::path>& complete, bool first) {
    std::vector<workflow::ReceivedScan> scans;
    std::string note;
    for (const net::ReceivedSeries& s : net::listReceivedSeries(dicom_.store, kSettle)) {
        // An incomplete series is listed, marked, but not offered as if whole (the load screen
        // and a script's $RECEIVED pass over what is not ready); a complete send clears it.
        scans.push_back({s.folder.string(), net::describe(s), s.arriving || s.incomplete});
        const bool seen = std::find(complete.begin(), complete.end(), s.folder) != complete.end();
        if (s.incomplete && !s.arriving && seen) {
            complete.erase(std::find(complete.begin(), complete.end(), s.folder));
        }
        if (s.incomplete && !s.arriving &&
            std::find(incomplete_.begin(), incomplete_.end(), s.folder) == incomplete_.end()) {
            incomplete_.push_back(s.folder);
            say("incomplete " + s.folder.string() + ": " + scans.back().label);
        }
        if (!s.incomplete) {
            std::erase(incomplete_, s.folder);
        }
        if (!s.arriving && !s.incomplete && !seen) {
            complete.push_back(s.folder);
            if (!first) {
                note = "New series: " + scans.back().label;
                say("received " + s.folder.string() + ": " + scans.back().label);
            }
        }
    }
    const std::lock_guard lock(mutex_);
    shared_.received = std::move(scans);
    if (!note.empty()) {
        shared_.note = std::move(note);
    }
}

void DicomNode::drain(net::Outbox& outbox) {
    net::SendOptions options = sendOptions(dicom_);
    options.timeoutSeconds = kSendTimeoutSeconds;
    outbox.deliverDue(
        [this](const std::string& name) { return sendPeer(dicom_, name); }, options,
        [this](const net::OutboxEntry& e, const net::SendOutcome& o) { recordSend(e, o); });
    publishPending(outbox, 0);
}

// Before the outbox updates or removes the entry: waits until the frame thread has written the
// attempt to the audit log (the log is the frame thread's), so that a kill -9 at any moment
// leaves no attempt the outbox counted without its record. A stop does not wait: finish()
// writes what is left.
void DicomNode::recordSend(const net::OutboxEntry& e, const net::SendOutcome& o) {
    std::unique_lock lock(mutex_);
    shared_.sends.push_back(
        {e.peer, e.source.string(), o.sopInstanceUid, o.problem, e.attempts, o.accepted});
    shared_.log.push_back(o.accepted ? "delivered " + e.source.string() + " to " + e.peer
                                     : "not delivered: " + waitingLine(e));
    const std::uint64_t handed = ++shared_.sendsHanded;
    wake_.wait(lock, [&] { return stop_ || shared_.sendsWritten >= handed; });
}

void DicomNode::take(workflow::AuditLog& audit, std::ostream& err) {
    std::vector<std::string> log;
    std::vector<SendRecord> sends;
    {
        const std::lock_guard lock(mutex_);
        log.swap(shared_.log);
        sends.swap(shared_.sends);
        received_ = shared_.received;
        outbox_ = shared_.outbox;
        // An export handed over but not yet queued is waiting too (a script waits for none).
        for (const fs::path& file : shared_.toQueue) {
            outbox_.push_back(file.filename().string() + ": queued");
        }
        note_ = shared_.note;
    }
    for (const std::string& line : log) {
        err << kLogPrefix << line << '\n';
    }
    for (const SendRecord& r : sends) {
        audit.send(r.peer, r.file, r.sopInstanceUid, r.attempt, r.accepted, r.problem);
    }
    if (!sends.empty()) {
        {
            const std::lock_guard lock(mutex_);
            shared_.sendsWritten += sends.size();
        }
        wake_.notify_all();
    }
}

void DicomNode::frame(const workflow::Status& status, workflow::AuditLog& audit,
                      std::ostream& err) {
    if (!dicom_.enabled) {
        return;
    }
    if (status.exports != exportsSeen_) {
        exportsSeen_ = status.exports;
        std::vector<fs::path> segs;
        for (const std::string& file : status.exportedFiles) {
            if (fs::path(file).extension() == ".dcm" && !peers_.empty()) {
                segs.emplace_back(file);
            }
        }
        if (!segs.empty()) {
            {
                const std::lock_guard lock(mutex_);
                shared_.toQueue.insert(shared_.toQueue.end(), segs.begin(), segs.end());
            }
            wake_.notify_all();
        }
    }
    take(audit, err);
    if (link_->pacs) {
        link_->pacs->take(audit, err, kLogPrefix);
    }
    // Loading a scan is the operator's answer to the note.
    if (status.state == model::State::Loading) {
        noteDismissed_ = note_;
    }
}

void DicomNode::request(const model::Action& action) {
    if (link_->pacs) {
        link_->pacs->request(action);
    } else if (dicom_.enabled) {
        say(std::string(model::actionName(action)) + ": no [[dicom.peers]] with query = true");
    }
}

void DicomNode::show(workflow::Status& status) const {
    if (link_->pacs) {
        link_->pacs->show(status.pacs);
    }
    status.received = received_;
    status.outbox = outbox_;
    status.receivedNote = note_ != noteDismissed_ ? note_ : "";
}

workflow::Status DicomNode::shown(const workflow::Status& status) const {
    workflow::Status s = status;
    show(s);
    return s;
}

void DicomNode::finish(workflow::AuditLog& audit, std::ostream& err) {
    stop();
    if (dicom_.enabled) {
        take(audit, err);
        if (link_->pacs) {
            link_->pacs->take(audit, err, kLogPrefix);
        }
    }
}

} // namespace steerseg::kiosk
