#pragma once

// The audit log: one JSON object per line, flushed as written, recording every action the
// workflow was given (accepted or refused, with its values and what it changed) and every state
// transition, each with the UTC time, seconds since the log opened and the scan's identity.
// docs/workflow.md lists the fields. The log must never stop the operator: a failure to open
// or write is kept and reported once (takeError), never thrown.
#include "model/action.hpp"
#include "workflow/settings.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::workflow {

using SteadyClock = std::function<std::chrono::steady_clock::time_point()>;

class AuditLog {
  public:
    // Appends to `path`, creating its folder. Empty clocks: the system's (tests fix them).
    explicit AuditLog(std::filesystem::path path, WallClock wall = {}, SteadyClock steady = {});
    ~AuditLog();
    AuditLog(const AuditLog&) = delete;
    AuditLog& operator=(const AuditLog&) = delete;

    // `state`: the state the action found. `result`: what it changed (null: nothing to add).
    // `reason`: empty for an accepted action, else why it was refused.
    void action(model::State state, const model::Action& action, const nlohmann::json& result,
                std::string_view scan, bool accepted, std::string_view reason);
    // `cause`: the action's name, or "load" / "evolve" for what update() and evolve() found.
    // `message`: the notice or error the new state shows ("" = none).
    void transition(model::State from, model::State to, std::string_view cause,
                    std::string_view scan, std::string_view message);

    // One attempt to send `file` (a DICOM object, `sopInstanceUid`) to a DICOM peer: the
    // outbox's record (docs/dicom-network.md). `problem`: "" when the peer accepted it.
    void send(std::string_view peer, std::string_view file, std::string_view sopInstanceUid,
              int attempt, bool accepted, std::string_view problem);

    [[nodiscard]] bool ok() const { return error_.empty(); }
    // The first failure, the first time it is asked for; nullopt afterwards and while all is well.
    std::optional<std::string> takeError();
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    void write(nlohmann::json& record);
    void fail(const std::string& what);

    std::filesystem::path path_;
    WallClock wall_;
    SteadyClock steady_;
    std::chrono::steady_clock::time_point opened_;
    std::FILE* file_ = nullptr;
    std::string error_;
    bool reported_ = false;
};

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

} // namespace steerseg::workflow
