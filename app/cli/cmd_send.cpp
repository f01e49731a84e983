// `steerseg send`: DICOM files to a peer over one association, one line per file; exit 0 only
// when the peer accepted every one (a site's integration test reads both). With --outbox the
// files go through the persistent outbox instead: queued durably first, then delivered with
// retries until the outbox is empty or --wait runs out.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/dicom_options.hpp"
#include "net/outbox.hpp"
#include "net/store_scu.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <thread>

namespace steerseg::cli {
namespace {

using std::chrono::steady_clock;
using std::chrono::system_clock;

int sendDirect(const Args& args, const config::KioskConfig& cfg,
               const std::vector<std::filesystem::path>& files) {
    const net::DicomPeer peer = sendTarget(args, cfg.dicom);
    if (files.empty()) {
        throw UsageError("give the DICOM files to send");
    }
    net::SendOptions options = kiosk::sendOptions(cfg.dicom);
    options.callingAet = ownAeTitle(args, cfg.dicom);
    const auto outcomes = net::sendFiles(peer, files, options);
    int failed = 0;
    for (const auto& o : outcomes) {
        if (o.accepted) {
            std::printf("accepted %s (%s)\n", o.file.c_str(), o.sopInstanceUid.c_str());
        } else {
            ++failed;
            std::printf("failed %s: %s\n", o.file.c_str(), o.problem.c_str());
        }
    }
    std::fflush(stdout);
    if (failed > 0) {
        throw std::runtime_error(std::to_string(failed) + " of " + std::to_string(outcomes.size()) +
                                 " object(s) not accepted by " + net::describe(peer));
    }
    return kExitOk;
}

// --outbox: FILE... (with --to PEER) are queued, then every due entry is sent, again and again
// as their delays come due, until none is left or --wait seconds have passed.
int sendThroughOutbox(const Args& args, const config::KioskConfig& cfg,
                      const std::vector<std::filesystem::path>& files) {
    const config::DicomConfig& dicom = cfg.dicom;
    const double waitSeconds = args.number("wait").value_or(0.0);
    if (waitSeconds < 0.0 || waitSeconds > 86400.0) {
        throw UsageError("--wait: 0..86400 seconds");
    }
    if (args.value("host") || args.value("port") || args.value("called-aet")) {
        throw UsageError("--outbox sends to configured peers only: give --to PEER");
    }
    if (!files.empty() && !args.value("to")) {
        throw UsageError("--outbox with files needs --to PEER");
    }
    std::string target;
    if (const auto to = args.value("to")) {
        // A name that is no send peer is the operator's mistake now, not a failed attempt later.
        requireSendPeer(dicom, *to);
        target = *to;
    }
    const auto peerNamed = [&](const std::string& name) { return sendPeer(dicom, name); };
    workflow::AuditLog audit(cfg.audit.path);
    net::Outbox outbox = configuredOutbox(dicom, audit);
    for (const auto& file : files) {
        std::printf("queued %s as %s\n", file.c_str(), outbox.enqueue(file, target).c_str());
    }
    net::SendOptions options = kiosk::sendOptions(dicom);
    options.callingAet = ownAeTitle(args, dicom);
    const auto report = [](const net::OutboxEntry& e, const net::SendOutcome& o) {
        if (o.accepted) {
            std::printf("delivered %s (%s) to %s\n", e.id.c_str(), e.source.c_str(),
                        e.peer.c_str());
        } else {
            const auto wait = std::chrono::duration<double>(e.nextAttempt - system_clock::now());
            std::printf("waiting %s (%s) for %s, attempt %d: %s; next in %.1f s\n", e.id.c_str(),
                        e.source.c_str(), e.peer.c_str(), e.attempts, o.problem.c_str(),
                        std::max(0.0, wait.count()));
        }
        std::fflush(stdout);
    };
    const auto deadline = steady_clock::now() + std::chrono::duration_cast<steady_clock::duration>(
                                                    std::chrono::duration<double>(waitSeconds));
    std::vector<net::OutboxEntry> left;
    while (true) {
        outbox.deliverDue(peerNamed, options, report);
        left = outbox.pending();
        if (left.empty() || steady_clock::now() >= deadline) {
            break;
        }
        // Until the earliest entry is due (pending() is in due order), within the deadline.
        const auto due = steady_clock::now() + (left.front().nextAttempt - system_clock::now());
        std::this_thread::sleep_until(std::min(due, deadline));
    }
    std::fflush(stdout);
    if (!left.empty()) {
        throw std::runtime_error(std::to_string(left.size()) + " object(s) still in the outbox " +
                                 outbox.folder().string() + ": " + left.front().lastProblem);
    }
    return kExitOk;
}

} // namespace

int runSend(std::span<const std::string> words) {
    const Args args(words, {"to", "host", "port", "called-aet", "aet", "config", "wait"},
                    {"outbox", "tls"});
    const config::KioskConfig cfg = nodeConfig(args);
    const std::vector<std::filesystem::path> files(args.positional().begin(),
                                                   args.positional().end());
    if (args.flag("outbox")) {
        return sendThroughOutbox(args, cfg, files);
    }
    if (args.value("wait")) {
        throw UsageError("--wait goes with --outbox");
    }
    return sendDirect(args, cfg, files);
}

} // namespace steerseg::cli
