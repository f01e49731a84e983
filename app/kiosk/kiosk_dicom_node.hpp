#pragma once

// The DICOM node inside the kiosk ([dicom] enabled = true; docs/dicom-network.md): the Storage
// SCP of `steerseg listen` on a thread of its own, and a worker thread that lists the incoming
// store for the load screen, puts each exported DICOM SEG into the persistent outbox for the
// send peers and drains the outbox as its delays come due. The frame thread only trades plain
// values with them under a lock once a frame: it never waits for the network or the disk.
#include "config/kiosk_config.hpp"
#include "workflow/status.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

namespace steerseg::workflow {
class AuditLog;
}
namespace steerseg::net {
class Outbox;
struct OutboxEntry;
struct SendOutcome;
} // namespace steerseg::net

namespace steerseg::kiosk {

class DicomNode {
  public:
    // A series whose newest image is younger than this is still arriving.
    static constexpr std::chrono::seconds kSettle{3};

    // Starts nothing when `dicom.enabled` is false. A port that cannot be bound (or no peer that
    // may call) is logged on the first frame; the kiosk runs on without receiving.
    explicit DicomNode(const config::DicomConfig& dicom);
    // Stops both threads (within a second, or the send in flight's network timeout).
    ~DicomNode();
    DicomNode(const DicomNode&) = delete;
    DicomNode& operator=(const DicomNode&) = delete;

    // Once a frame on the frame thread: the node's news to `err`, its send attempts to `audit`
    // (the log is the frame thread's), a new export's DICOM files to the outbox, and the lists
    // for the panel into `status`.
    void frame(const workflow::Status& status, workflow::AuditLog& audit, std::ostream& err);
    // A PACS action the workflow accepted (SearchPacs, ListPacsSeries, RetrievePacs,
    // CancelRetrieve), for the node's PACS client (kiosk_pacs); others are ignored. Returns at
    // once.
    void request(const model::Action& action);
    // The panel's and a script's view: `status` with the received series, the note of a new
    // one (until the operator loads a scan) and the outbox's lines, as of the last frame().
    void show(workflow::Status& status) const;
    [[nodiscard]] workflow::Status shown(const workflow::Status& status) const;
    // Stops both threads and hands over what they had left (the kiosk's last frame).
    void finish(workflow::AuditLog& audit, std::ostream& err);

  private:
    struct SendRecord {
        std::string peer, file, sopInstanceUid, problem;
        int attempt = 0;
        bool accepted = false;
    };
    // What the threads hand the frame thread; guarded by mutex_.
    struct Shared {
        std::vector<std::string> log;
        std::vector<SendRecord> sends;
        std::vector<workflow::ReceivedScan> received;
        std::string note;
        std::vector<std::string> outbox;
        std::vector<std::filesystem::path> toQueue; // the frame thread's, for the worker
        // Send records handed to the frame thread, and how many of them it has written to the
        // audit log: an attempt is on record before the outbox moves past it.
        std::uint64_t sendsHanded = 0;
        std::uint64_t sendsWritten = 0;
    };

    void stop();
    void work();
    void recordSend(const net::OutboxEntry& entry, const net::SendOutcome& outcome);
    void queueExports(net::Outbox& outbox);
    void listStore(std::vector<std::filesystem::path>& complete, bool first);
    void drain(net::Outbox& outbox);
    void publishPending(const net::Outbox& outbox, std::size_t handedOver);
    void say(const std::string& line);
    void take(workflow::AuditLog& audit, std::ostream& err);

    config::DicomConfig dicom_;
    std::atomic<bool> stop_{false};
    std::mutex mutex_;
    std::condition_variable wake_;
    Shared shared_;
    int exportsSeen_ = 0;
    std::vector<std::filesystem::path> incomplete_; // the worker's: said once each
    std::vector<std::string> peers_;                // where exports go: the send peers' names
    // The frame thread's copy of the lists, and the note the operator has moved past.
    std::vector<workflow::ReceivedScan> received_;
    std::vector<std::string> outbox_;
    std::string note_;
    std::string noteDismissed_;
    // The Storage SCP, the outbox's files (the worker's after the constructor) and the PACS
    // client: net's in the
    // full build (kiosk_dicom_node.cpp); the light build (kiosk_dicom_node_light.cpp) has none.
    struct Link;
    std::unique_ptr<Link> link_;
    std::thread scpThread_;
    std::thread worker_;
};

} // namespace steerseg::kiosk
