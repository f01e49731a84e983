#include "workflow/audit_log.hpp"

#include "files/file_append.hpp"
#include "files/file_error.hpp"
#include "workflow/utc_time.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace steerseg::workflow {

namespace {

constexpr std::size_t kMaxHeld = 100000; // a day of a busy console's records, a few tens of MB
constexpr std::chrono::seconds kRetryEvery{1};

std::string readAll(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

bool wholeRecord(const std::string& line) {
    try {
        return nlohmann::json::parse(line).is_object();
    } catch (const std::exception&) {
        return false;
    }
}

} // namespace

std::optional<std::string> repairTornTail(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        return std::nullopt;
    }
    const std::string text = readAll(path);
    const std::size_t cut =
        text.find_last_of('\n') == std::string::npos ? 0 : text.find_last_of('\n') + 1;
    const std::string tail = text.substr(cut);
    if (tail.empty()) {
        return std::nullopt;
    }
    if (wholeRecord(tail)) {
        files::AppendFile(path).append("\n");
        return "audit log " + path.string() + ": the last record lacked its newline; added";
    }
    std::filesystem::path aside = path;
    aside += ".torn";
    files::AppendFile(aside).append(tail + "\n");
    std::filesystem::resize_file(path, cut, ec);
    if (ec) {
        throw files::WriteError(path, "cannot cut off the torn last record: " + ec.message());
    }
    return "audit log " + path.string() + ": a torn last record (" + std::to_string(tail.size()) +
           " bytes, from a crash) moved to " + aside.string();
}

AuditLog::AuditLog(std::filesystem::path path, WallClock wall, SteadyClock steady)
    : path_(std::move(path)), wall_(std::move(wall)), steady_(std::move(steady)) {
    if (!wall_) {
        wall_ = [] { return std::chrono::system_clock::now(); };
    }
    if (!steady_) {
        steady_ = [] { return std::chrono::steady_clock::now(); };
    }
    opened_ = steady_();
    lastTry_ = opened_;
    flush();
}

AuditLog::~AuditLog() = default;

void AuditLog::fail(const std::string& what) {
    if (problem_.empty()) {
        untold_.push_back("audit log " + what);
    }
    problem_ = "audit log " + what;
    file_.reset(); // reopened on the next try: the file may have been replaced meanwhile
}

std::optional<std::string> AuditLog::takeError() {
    if (untold_.empty()) {
        return std::nullopt;
    }
    std::string oldest = std::move(untold_.front());
    untold_.pop_front();
    return oldest;
}

std::optional<std::string> AuditLog::takeRepairNote() {
    return std::exchange(repairNote_, std::nullopt);
}

void AuditLog::flush() {
    lastTry_ = steady_();
    try {
        if (!file_) {
            // Before every opening, the first and each after an outage: no record may be glued
            // onto a torn line.
            if (auto note = repairTornTail(path_)) {
                repairNote_ = std::move(note);
            }
            file_ = std::make_unique<files::AppendFile>(path_);
        }
        while (!held_.empty()) {
            file_->append(held_.front());
            held_.pop_front();
        }
    } catch (const std::exception& e) {
        fail(e.what());
        return;
    }
    if (!problem_.empty()) {
        untold_.push_back("audit log " + path_.string() + ": written again" +
                          (dropped_ > 0
                               ? ", " + std::to_string(dropped_) + " records lost meanwhile"
                               : std::string()));
        problem_.clear();
        dropped_ = 0;
    }
}

void AuditLog::retry() {
    if (!problem_.empty() && steady_() - lastTry_ >= kRetryEvery) {
        flush();
    }
}

void AuditLog::write(nlohmann::json& record) {
    try {
        const std::chrono::duration<double> since = steady_() - opened_;
        record["time"] = isoUtc(wall_());
        record["mono"] = since.count();
        // Paths and names come from operators and scripts: bad UTF-8 is replaced, not thrown.
        std::string line = record.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        line += '\n';
        if (held_.size() >= kMaxHeld) {
            held_.pop_front();
            ++dropped_;
        }
        held_.push_back(std::move(line));
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
        return;
    }
    flush();
}

void AuditLog::action(model::State state, const model::Action& action, const nlohmann::json& result,
                      std::string_view scan, bool accepted, std::string_view reason,
                      std::string_view structure) {
    try {
        nlohmann::json r{{"event", "action"},
                         {"state", model::stateName(state)},
                         {"action", model::actionName(action)},
                         {"values", actionValues(action)},
                         {"accepted", accepted},
                         {"scan", scan}};
        if (!structure.empty()) {
            r["structure"] = structure;
        }
        if (!result.is_null()) {
            r["result"] = result;
        }
        if (!accepted) {
            r["reason"] = reason;
        }
        write(r);
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
    }
}

void AuditLog::transition(model::State from, model::State to, std::string_view cause,
                          std::string_view scan, std::string_view message) {
    try {
        nlohmann::json r{{"event", "transition"},
                         {"from", model::stateName(from)},
                         {"to", model::stateName(to)},
                         {"state", model::stateName(to)},
                         {"cause", cause},
                         {"scan", scan}};
        if (!message.empty()) {
            r["message"] = message;
        }
        write(r);
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
    }
}

void AuditLog::numericsCheck(bool passed, const nlohmann::json& speeds, double seconds) {
    try {
        nlohmann::json r{{"event", "numerics_check"},
                         {"passed", passed},
                         {"speeds", speeds},
                         {"seconds", seconds}};
        write(r);
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
    }
}

void AuditLog::send(std::string_view peer, std::string_view file, std::string_view sopInstanceUid,
                    int attempt, bool accepted, std::string_view problem) {
    try {
        nlohmann::json r{{"event", "send"},    {"peer", peer},
                         {"file", file},       {"sop_instance_uid", sopInstanceUid},
                         {"attempt", attempt}, {"accepted", accepted}};
        if (!accepted) {
            r["problem"] = problem;
        }
        write(r);
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
    }
}

void AuditLog::pacs(std::string_view event, const nlohmann::json& fields) {
    try {
        nlohmann::json r{{"event", event}};
        r.update(fields);
        write(r);
    } catch (const std::exception& e) {
        fail(path_.string() + ": record failed: " + e.what());
    }
}

AuditLogContents readAuditLog(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error("audit log " + path.string() + ": cannot open it");
    }
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    AuditLogContents out;
    std::size_t at = 0;
    std::size_t lineNo = 0;
    while (at < text.size()) {
        ++lineNo;
        const std::size_t nl = text.find('\n', at);
        const bool last = nl == std::string::npos || nl + 1 == text.size();
        const std::string line =
            text.substr(at, nl == std::string::npos ? std::string::npos : nl - at);
        at = nl == std::string::npos ? text.size() : nl + 1;
        if (line.empty()) {
            continue; // the separator a resumed log writes after a torn line
        }
        const std::string where = "line " + std::to_string(lineNo) + ": ";
        try {
            nlohmann::json record = nlohmann::json::parse(line);
            if (!record.is_object()) {
                throw std::runtime_error("not a JSON object");
            }
            if (nl == std::string::npos) {
                // The record is whole but its newline never made it to the disk.
                out.torn = where + "no newline at the end; the record is whole and kept";
            }
            out.records.push_back(std::move(record));
        } catch (const std::exception&) {
            const std::string what =
                where + std::to_string(line.size()) + " bytes that are not a whole record";
            if (last) {
                out.torn = what;
            } else {
                out.problems.push_back(what);
            }
        }
    }
    return out;
}

} // namespace steerseg::workflow
