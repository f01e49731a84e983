#pragma once

// The audit log: one JSON object per line, synced as written, recording every action the
// workflow was given (accepted or refused, with its values and what it changed) and every state
// transition, each with the UTC time, seconds since the log opened and the scan's identity.
// docs/workflow.md lists the fields. The log must never stop the operator, and never go quiet:
// a failure to open or write is never thrown; the records wait in memory and go out, in order
// and with their own times, as soon as the file can be written again (retry), while problem()
// says why it cannot, for the screen (which shows it until it clears) and the journal.
#include "model/action.hpp"
#include "workflow/settings.hpp"

#include <chrono>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::files {
class AppendFile;
}

namespace steerseg::workflow {

using SteadyClock = std::function<std::chrono::steady_clock::time_point()>;

class AuditLog {
  public:
    // Appends to `path`, creating its folder, after a torn last record left by a crash is moved
    // aside (repairTornTail). Empty clocks: the system's (tests fix them).
    explicit AuditLog(std::filesystem::path path, WallClock wall = {}, SteadyClock steady = {});
    ~AuditLog();
    AuditLog(const AuditLog&) = delete;
    AuditLog& operator=(const AuditLog&) = delete;

    // `state`: the state the action found. `result`: what it changed (null: nothing to add).
    // `reason`: empty for an accepted action, else why it was refused. `structure`: the
    // structure that was active when it came ("" before a scan has one).
    void action(model::State state, const model::Action& action, const nlohmann::json& result,
                std::string_view scan, bool accepted, std::string_view reason,
                std::string_view structure = {});
    // `cause`: the action's name, or "load" / "evolve" for what update() and evolve() found.
    // `message`: the notice or error the new state shows ("" = none).
    void transition(model::State from, model::State to, std::string_view cause,
                    std::string_view scan, std::string_view message);

    // The start-up check of this GPU's numbers (session/numerics_check): `speeds` holds one
    // object per speed (name, passed, largest difference, detail).
    void numericsCheck(bool passed, const nlohmann::json& speeds, double seconds);
    // One attempt to send `file` (a DICOM object, `sopInstanceUid`) to a DICOM peer: the
    // outbox's record (docs/dicom-network.md). `problem`: "" when the peer accepted it.
    void send(std::string_view peer, std::string_view file, std::string_view sopInstanceUid,
              int attempt, bool accepted, std::string_view problem);
    // A PACS search or retrieve the kiosk's DICOM node ran (docs/dicom-network.md "The kiosk's
    // search"): `event` "query" or "retrieve", `fields` what it asked, of whom, and how it ended.
    void pacs(std::string_view event, const nlohmann::json& fields);

    // While the log cannot be written: tries again, at most once a second (the frame loop
    // calls it every frame), writing the records held meanwhile.
    void retry();

    [[nodiscard]] bool ok() const { return problem_.empty(); }
    // Why the log cannot be written now, one line ("" while it can).
    [[nodiscard]] const std::string& problem() const { return problem_; }
    // Records waiting for the file to be writable again.
    [[nodiscard]] std::size_t held() const { return held_.size(); }
    // The oldest failure (or recovery) not yet told, once each: for the journal.
    std::optional<std::string> takeError();
    // What the opening repaired, once (nullopt when nothing).
    std::optional<std::string> takeRepairNote();
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    void write(nlohmann::json& record);
    void flush();
    void fail(const std::string& what);

    std::filesystem::path path_;
    WallClock wall_;
    SteadyClock steady_;
    std::chrono::steady_clock::time_point opened_;
    std::chrono::steady_clock::time_point lastTry_;
    std::unique_ptr<files::AppendFile> file_;
    std::deque<std::string> held_; // lines not yet written, oldest first
    std::size_t dropped_ = 0;      // lines lost past kMaxHeld
    std::string problem_;
    std::deque<std::string> untold_; // outages and recoveries for takeError, oldest first
    std::optional<std::string> repairNote_;
};

// A crash or power cut mid-write leaves the last line torn. Before the log is appended to again
// the fragment is moved to `<path>.torn` (appended there) and the log cut back to its last whole
// line, so the file stays valid JSON lines; a whole record that only lacks its newline gets it.
// Returns what it did in one line (nullopt: nothing to repair). Throws files::WriteError when
// it cannot.
std::optional<std::string> repairTornTail(const std::filesystem::path& path);

// An audit log read back, e.g. by a resumed session that goes on writing it. A crash or power
// cut can tear the last line (no newline, or cut inside the JSON): it is skipped and described
// in `torn`; a damaged line before it is skipped and described in `problems`.
struct AuditLogContents {
    std::vector<nlohmann::json> records;
    std::optional<std::string> torn;   // "line N: ..." when the last line was torn
    std::vector<std::string> problems; // "line N: ..." for each other line skipped
};
// Throws std::runtime_error naming the file when it cannot be read (a missing file included).
AuditLogContents readAuditLog(const std::filesystem::path& path);

// The action's arguments as a JSON object ({} for actions without any): the audit log's
// "values" and a script's round trip.
nlohmann::json actionValues(const model::Action& action);
// A box as the audit log and the autosave write it: {"lo": [i, j, k], "hi": [i, j, k]}.
nlohmann::json boxValues(const model::Box& box);

} // namespace steerseg::workflow
