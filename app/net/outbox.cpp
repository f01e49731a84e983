#include "net/outbox.hpp"

#include "files/file_error.hpp"
#include "files/file_write.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

namespace steerseg::net {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;
using std::chrono::system_clock;

long long toMs(system_clock::time_point t) {
    return std::chrono::duration_cast<milliseconds>(t.time_since_epoch()).count();
}

system_clock::time_point fromMs(long long ms) {
    return system_clock::time_point(
        std::chrono::duration_cast<system_clock::duration>(milliseconds(ms)));
}

std::vector<std::byte> readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw files::FileError(path, "cannot be read");
    }
    std::vector<char> text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        throw files::FileError(path, "read error");
    }
    const auto* bytes = reinterpret_cast<const std::byte*>(text.data());
    return {bytes, bytes + text.size()};
}

} // namespace

Outbox::Outbox(fs::path folder, OutboxBackoff backoff, workflow::AuditLog* audit, SystemClock clock)
    : folder_(std::move(folder)), backoff_(backoff), audit_(audit), clock_(std::move(clock)) {
    if (!clock_) {
        clock_ = [] { return system_clock::now(); };
    }
    std::error_code ignored;
    fs::create_directories(folder_, ignored);
}

std::chrono::milliseconds Outbox::delayAfter(int attempts) const {
    milliseconds delay = backoff_.first;
    for (int n = 1; n < attempts && delay < backoff_.longest; ++n) {
        delay *= 2;
    }
    return std::min(delay, backoff_.longest);
}

void Outbox::writeRecord(const OutboxEntry& e) const {
    const nlohmann::json record{{"peer", e.peer},
                                {"source", e.source.string()},
                                {"attempts", e.attempts},
                                {"next_attempt_ms", toMs(e.nextAttempt)},
                                {"last_problem", e.lastProblem}};
    const std::string text = record.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    files::writeFileAtomically(folder_ / (e.id + ".json"),
                               {std::as_bytes(std::span(text.data(), text.size()))});
}

std::string Outbox::enqueue(const fs::path& file, const std::string& peer) {
    const std::vector<std::byte> bytes = readBytes(file);
    // Sortable by time; the counter keeps two entries of one millisecond apart.
    const long long now = toMs(clock_());
    std::string id;
    for (int n = 0;; ++n) {
        id = std::to_string(now) + "-" + std::to_string(n);
        if (!fs::exists(folder_ / (id + ".dcm")) && !fs::exists(folder_ / (id + ".json"))) {
            break;
        }
    }
    OutboxEntry entry{id, peer, fs::absolute(file), folder_ / (id + ".dcm"), 0, clock_(), ""};
    files::writeFileAtomically(entry.object, {std::span<const std::byte>(bytes)});
    try {
        writeRecord(entry);
    } catch (...) {
        // An object without its record would never be sent nor listed: take it back, so a
        // failed enqueue leaves the outbox as it was (the caller has the error).
        std::error_code ec;
        fs::remove(entry.object, ec);
        throw;
    }
    return id;
}

std::vector<OutboxEntry> Outbox::pending(std::vector<std::string>* problems) const {
    std::vector<OutboxEntry> entries;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(folder_, ec)) {
        const fs::path& path = item.path();
        if (path.extension() != ".json" || path.filename().string().front() == '.') {
            continue;
        }
        OutboxEntry e;
        e.id = path.stem().string();
        e.object = folder_ / (e.id + ".dcm");
        try {
            std::ifstream in(path);
            const nlohmann::json record = nlohmann::json::parse(in);
            e.peer = record.at("peer").get<std::string>();
            e.source = record.at("source").get<std::string>();
            e.attempts = record.at("attempts").get<int>();
            e.nextAttempt = fromMs(record.at("next_attempt_ms").get<long long>());
            e.lastProblem = record.at("last_problem").get<std::string>();
        } catch (const std::exception& error) {
            if (problems != nullptr) {
                problems->push_back(path.string() + ": not an outbox record (" + error.what() +
                                    ")");
            }
            continue;
        }
        if (!fs::exists(e.object)) {
            if (problems != nullptr) {
                problems->push_back(path.string() + ": its object " + e.object.string() +
                                    " is missing");
            }
            continue;
        }
        entries.push_back(std::move(e));
    }
    std::sort(entries.begin(), entries.end(), [](const OutboxEntry& a, const OutboxEntry& b) {
        return std::make_pair(a.nextAttempt, a.id) < std::make_pair(b.nextAttempt, b.id);
    });
    return entries;
}

int Outbox::deliverDue(
    const std::function<std::optional<DicomPeer>(const std::string&)>& resolve,
    const SendOptions& options,
    const std::function<void(const OutboxEntry&, const SendOutcome&)>& attempted) {
    int delivered = 0;
    for (OutboxEntry& e : pending()) {
        if (e.nextAttempt > clock_()) {
            continue;
        }
        SendOutcome outcome;
        if (const auto peer = resolve(e.peer)) {
            outcome = sendFiles(*peer, std::vector<fs::path>{e.object}, options).front();
        } else {
            outcome.problem = "no peer named '" + e.peer + "' to send to";
        }
        ++e.attempts;
        if (audit_ != nullptr) {
            audit_->send(e.peer, e.source.string(), outcome.sopInstanceUid, e.attempts,
                         outcome.accepted, outcome.problem);
        }
        if (!outcome.accepted) {
            e.lastProblem = outcome.problem;
            e.nextAttempt = clock_() + delayAfter(e.attempts);
        }
        if (attempted) {
            attempted(e, outcome);
        }
        std::error_code ignored;
        if (outcome.accepted) {
            fs::remove(folder_ / (e.id + ".json"), ignored);
            fs::remove(e.object, ignored);
            ++delivered;
        } else {
            writeRecord(e);
        }
    }
    return delivered;
}

} // namespace steerseg::net
