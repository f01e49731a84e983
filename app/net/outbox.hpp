#pragma once

// The persistent outbox: what the console sends to a PACS is first written into a folder
// (durably, files::writeFileAtomically), then sent; an attempt that fails is kept and retried
// with a growing delay, across restarts and power cuts, and every attempt goes to the audit log.
// Each entry is two files, <id>.dcm (the object) and <id>.json (its record: the peer, the
// attempts, when the next is due, the last problem); the record is written after the object and
// removed before it, so a record always has its object. An entry whose peer accepted it but
// whose removal a crash cut short is sent once more: a PACS keys instances by SOP Instance UID,
// so its instance list still shows it once.
#include "net/dicom_peer.hpp"
#include "net/store_scu.hpp"

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::workflow {
class AuditLog;
}

namespace steerseg::net {

struct OutboxBackoff {
    // The delay after the first failed attempt, doubled after each further one up to `longest`.
    std::chrono::milliseconds first{5000};
    std::chrono::milliseconds longest{std::chrono::minutes(5)};
};

using SystemClock = std::function<std::chrono::system_clock::time_point()>;

struct OutboxEntry {
    std::string id;
    std::string peer;             // a [[dicom.peers]] name
    std::filesystem::path source; // the file it was made from, for the log and the panel
    std::filesystem::path object; // the copy in the outbox
    int attempts = 0;
    std::chrono::system_clock::time_point nextAttempt;
    std::string lastProblem; // why the last attempt failed ("" before the first)
};

class Outbox {
  public:
    // Creates `folder` if needed. `audit` (may be null) records every attempt. Empty clock: the
    // system's.
    Outbox(std::filesystem::path folder, OutboxBackoff backoff = {},
           workflow::AuditLog* audit = nullptr, SystemClock clock = {});

    // Copies `file` into the outbox for `peer`, due at once; returns the entry's id. Throws
    // files::WriteError (or FileError when `file` cannot be read): nothing is queued then.
    std::string enqueue(const std::filesystem::path& file, const std::string& peer);

    // The entries waiting, oldest first. A record that cannot be read is skipped and named in
    // `problems` (when given), never thrown.
    [[nodiscard]] std::vector<OutboxEntry>
    pending(std::vector<std::string>* problems = nullptr) const;

    // One pass over the entries that are due: each is sent on its own association; a delivered
    // one is removed, a failed one rescheduled. `resolve` turns a peer's name into its address
    // (nullopt: no such peer, a failed attempt too). Returns how many were delivered.
    // `attempted` (may be empty) hears of each attempt, the entry as it is after it, before the
    // entry's files are updated or removed: what it records of the attempt (an audit log) is
    // then never behind the outbox, whenever the process dies.
    int
    deliverDue(const std::function<std::optional<DicomPeer>(const std::string&)>& resolve,
               const SendOptions& options,
               const std::function<void(const OutboxEntry&, const SendOutcome&)>& attempted = {});

    // The delay after `attempts` failed attempts.
    [[nodiscard]] std::chrono::milliseconds delayAfter(int attempts) const;

    [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }

  private:
    void writeRecord(const OutboxEntry& entry) const;

    std::filesystem::path folder_;
    OutboxBackoff backoff_;
    workflow::AuditLog* audit_;
    SystemClock clock_;
};

} // namespace steerseg::net
