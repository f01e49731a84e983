#include "kiosk/kiosk_pacs.hpp"

#include "kiosk/dicom_node_config.hpp"
#include "net/query_scu.hpp"
#include "net/retrieve_scu.hpp"
#include "workflow/audit_log.hpp"

#include <algorithm>
#include <ctime>

namespace steerseg::kiosk {
namespace {

// A page of studies is what a touch list can show; more is a search to narrow.
constexpr std::size_t kMaxStudies = 200;

std::chrono::year_month_day localToday() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    return std::chrono::year_month_day{std::chrono::year(local.tm_year + 1900),
                                       std::chrono::month(static_cast<unsigned>(local.tm_mon + 1)),
                                       std::chrono::day(static_cast<unsigned>(local.tm_mday))};
}

std::string dashedDate(const std::string& yyyymmdd) {
    if (yyyymmdd.size() != 8) {
        return yyyymmdd;
    }
    return yyyymmdd.substr(0, 4) + "-" + yyyymmdd.substr(4, 2) + "-" + yyyymmdd.substr(6, 2);
}

// "2026-11-20  DOE JANE (ID 12345)  CT  Chest  (3 series, 120 images)": what tells studies apart.
std::string studyLabel(const net::StudyMatch& s) {
    std::string name = s.patientName;
    std::replace(name.begin(), name.end(), '^', ' ');
    std::string line = dashedDate(s.studyDate);
    for (const std::string& part : {name, s.patientId.empty() ? "" : "(ID " + s.patientId + ")",
                                    s.modalities, s.description}) {
        if (!part.empty()) {
            line += (line.empty() ? "" : "  ") + part;
        }
    }
    if (s.seriesCount >= 0 || s.instanceCount >= 0) {
        line += "  (";
        if (s.seriesCount >= 0) {
            line += std::to_string(s.seriesCount) + " series";
        }
        if (s.instanceCount >= 0) {
            line += (s.seriesCount >= 0 ? ", " : "") + std::to_string(s.instanceCount) + " images";
        }
        line += ")";
    }
    return line;
}

// The peer's association options for a question or a retrieve: the send options, the query's
// timeout.
net::ScuOptions queryOptions(const config::DicomConfig& dicom) {
    net::ScuOptions options = sendOptions(dicom);
    options.timeoutSeconds = dicom.queryTimeoutSeconds;
    return options;
}

std::string noQueryPeer(const std::string& name) {
    return "no [[dicom.peers]] named '" + name + "' with query = true";
}

std::string ofExpected(const net::RetrieveProgress& p) {
    return std::to_string(p.received) +
           (p.expected > 0 ? " of " + std::to_string(p.expected) : "") + " images" +
           (p.failed > 0 ? " (" + std::to_string(p.failed) + " failed)" : "");
}

} // namespace

PacsClient::PacsClient(const config::DicomConfig& dicom, bool listening)
    : dicom_(dicom), listening_(listening) {
    for (const config::DicomPeerConfig& p : dicom_.peers) {
        if (p.query) {
            queryPeers_.push_back(p.name);
        }
    }
    shared_.view.peers = queryPeers_;
    shared_.view.fields = dicom_.searchFields;
    shared_.view.datePresets = dicom_.searchDatePresets;
    shown_ = shared_.view;
    searchThread_ = std::thread([this] { searchLoop(); });
    retrieveThread_ = std::thread([this] { retrieveLoop(); });
}

PacsClient::~PacsClient() {
    stop();
}

void PacsClient::stop() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
        cancel_ = true; // a retrieve under way ends with C-CANCEL, not at its last image
    }
    wake_.notify_all();
    if (searchThread_.joinable()) {
        searchThread_.join();
    }
    if (retrieveThread_.joinable()) {
        retrieveThread_.join();
    }
}

std::string PacsClient::peerName(const std::string& asked) const {
    if (!asked.empty() || queryPeers_.empty()) {
        return asked;
    }
    return queryPeers_.front();
}

void PacsClient::request(const model::Action& action) {
    const std::lock_guard lock(mutex_);
    if (const auto* s = std::get_if<model::SearchPacs>(&action)) {
        shared_.search = *s;
    } else if (const auto* l = std::get_if<model::ListPacsSeries>(&action)) {
        shared_.series = *l;
        // Shown at once, the rows of another study gone: the tap is answered in the next frame.
        shared_.view.listingSeries = true;
        shared_.view.seriesStudyUid = l->studyUid;
        shared_.view.seriesPeer = peerName(l->peer);
        shared_.view.series.clear();
        shared_.view.seriesLine = "listing the series on " + shared_.view.seriesPeer + "...";
    } else if (const auto* r = std::get_if<model::RetrievePacs>(&action)) {
        if (shared_.view.retrieving || shared_.retrieve) {
            shared_.log.push_back("retrieve of " + r->studyUid +
                                  " refused: a retrieve is under way (cancel it first)");
            return;
        }
        shared_.retrieve = *r;
        cancel_ = false;
        // Shown at once: the operator's tap is answered in the next frame, not the thread's.
        shared_.view.retrieving = true;
        shared_.view.received = shared_.view.failed = shared_.view.expected = 0;
        shared_.view.retrieveLine = "retrieving from " + peerName(r->peer) + "...";
    } else if (std::holds_alternative<model::CancelRetrieve>(action)) {
        if (shared_.view.retrieving) {
            cancel_ = true;
            shared_.view.retrieveLine = "cancelling the retrieve...";
        }
    }
    wake_.notify_all();
}

void PacsClient::searchLoop() {
    for (;;) {
        std::optional<model::SearchPacs> search;
        std::optional<model::ListPacsSeries> series;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] {
                return stop_ || shared_.search.has_value() || shared_.series.has_value();
            });
            if (stop_) {
                return;
            }
            if (shared_.search) {
                search = std::exchange(shared_.search, std::nullopt);
                shared_.view.searching = true;
                shared_.view.searchLine = "searching " + peerName(search->peer) + "...";
            } else {
                series = std::exchange(shared_.series, std::nullopt);
            }
        }
        if (search) {
            runSearch(*search);
        } else {
            runSeries(*series);
        }
    }
}

void PacsClient::retrieveLoop() {
    for (;;) {
        model::RetrievePacs request;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || shared_.retrieve.has_value(); });
            if (stop_) {
                return;
            }
            request = *shared_.retrieve; // kept until it ends: a second one is refused meanwhile
        }
        runRetrieve(request);
    }
}

void PacsClient::runSearch(const model::SearchPacs& request) {
    const std::string name = peerName(request.peer);
    net::StudyQuery query{request.keys.patientName, request.keys.patientId,
                          model::studyDateFor(request.keys.studyDate, localToday()),
                          request.keys.modality, request.keys.accession};
    std::vector<workflow::PacsStudy> studies;
    std::string line;
    std::string problem;
    const std::optional<QueryPeer> peer = queryPeer(dicom_, name);
    if (!peer) {
        problem = noQueryPeer(name);
    } else if (problem = net::studyQueryProblem(query); problem.empty()) {
        const net::ScuOptions options = queryOptions(dicom_);
        const net::QueryResult<net::StudyMatch> found =
            net::findStudies(peer->peer, query, options, kMaxStudies);
        problem = found.problem;
        for (const net::StudyMatch& s : found.matches) {
            studies.push_back({s.studyUid, studyLabel(s)});
        }
        line = std::to_string(studies.size()) + (studies.size() == 1 ? " study" : " studies") +
               " on " + name +
               (found.truncated
                    ? " (the first " + std::to_string(kMaxStudies) + " only: narrow the search)"
                    : "") +
               (found.leftOut.empty() ? "" : "; " + found.leftOut);
    }
    if (!problem.empty()) {
        line = "search on " + name + " failed: " + problem;
    }
    const std::lock_guard lock(mutex_);
    shared_.view.searching = false;
    ++shared_.view.searches;
    shared_.view.searchLine = line;
    shared_.view.studies = std::move(studies);
    shared_.view.studiesPeer = name;
    shared_.log.push_back(line);
    shared_.audit.emplace_back("query", nlohmann::json{{"peer", name},
                                                       {"level", "study"},
                                                       {"patient_name", query.patientName},
                                                       {"patient_id", query.patientId},
                                                       {"study_date", query.studyDate},
                                                       {"modality", query.modality},
                                                       {"accession", query.accession},
                                                       {"matches", shared_.view.studies.size()},
                                                       {"problem", problem}});
}

void PacsClient::runSeries(const model::ListPacsSeries& request) {
    const std::string name = peerName(request.peer);
    std::vector<workflow::PacsSeries> series;
    std::string line;
    std::string problem;
    const std::optional<QueryPeer> peer = queryPeer(dicom_, name);
    if (!peer) {
        problem = noQueryPeer(name);
    } else if (problem = model::uidProblem(request.studyUid); problem.empty()) {
        const net::ScuOptions options = queryOptions(dicom_);
        const net::QueryResult<net::SeriesMatch> found =
            net::findSeries(peer->peer, request.studyUid, options, kMaxStudies);
        problem = found.problem;
        for (const net::SeriesMatch& s : found.matches) {
            series.push_back({s.seriesUid, s.modality, s.number, s.description, s.instanceCount});
        }
        line = std::to_string(series.size()) + " series of the study on " + name +
               (found.truncated ? " (the first " + std::to_string(kMaxStudies) + " only)" : "") +
               (found.leftOut.empty() ? "" : "; " + found.leftOut);
    }
    if (!problem.empty()) {
        line = "series of the study on " + name + " failed: " + problem;
    }
    const std::size_t matches = series.size();
    const std::lock_guard lock(mutex_);
    const bool newer = shared_.series.has_value(); // another study asked meanwhile: it shows
    if (!newer) {
        shared_.view.listingSeries = false;
        shared_.view.seriesLine = line;
        shared_.view.seriesStudyUid = request.studyUid;
        shared_.view.seriesPeer = name;
        shared_.view.series = std::move(series);
    }
    ++shared_.view.seriesListings;
    shared_.log.push_back(line);
    shared_.audit.emplace_back("query", nlohmann::json{{"peer", name},
                                                       {"level", "series"},
                                                       {"study", request.studyUid},
                                                       {"matches", matches},
                                                       {"problem", problem}});
}

void PacsClient::runRetrieve(const model::RetrievePacs& request) {
    const std::string name = peerName(request.peer);
    net::RetrieveOutcome outcome;
    const std::optional<QueryPeer> peer = queryPeer(dicom_, name);
    net::RetrieveOptions how;
    if (!peer) {
        outcome.problem = noQueryPeer(name);
    } else {
        how.method = peer->retrieve;
        how.store = dicom_.store;
        how.minFreeBytes = static_cast<std::uint64_t>(dicom_.minFreeMb) << 20;
        how.moveDestination = dicom_.aet;
        if (how.method == net::RetrieveMethod::Move && !listening_) {
            // The images of a C-MOVE come to the node's port: with none open they would fail
            // one by one at the PACS.
            outcome.problem = "retrieve = \"move\" needs the node receiving on its port, and it "
                              "is not (see the log's first dicom line)";
        } else {
            const net::ScuOptions options = queryOptions(dicom_);
            outcome = net::retrieve(
                peer->peer, {request.studyUid, request.seriesUid}, how, options,
                [this, &name](const net::RetrieveProgress& p) {
                    const std::lock_guard lock(mutex_);
                    shared_.view.received = p.received;
                    shared_.view.failed = p.failed;
                    shared_.view.expected = p.expected;
                    if (!cancel_) {
                        shared_.view.retrieveLine =
                            "retrieving " + ofExpected(p) + " from " + name + "...";
                    }
                },
                [this] { return cancel_.load(); });
        }
    }
    const net::RetrieveProgress& p = outcome.progress;
    std::string line;
    if (outcome.cancelled) {
        line = "retrieve from " + name + " cancelled after " + ofExpected(p) +
               "; what came is kept, listed as incomplete";
    } else if (outcome.problem.empty()) {
        line = "retrieved " + ofExpected(p) + " from " + name + ": listed under Received";
    } else {
        line = "retrieve from " + name + " failed after " + ofExpected(p) + ": " + outcome.problem;
    }
    const std::lock_guard lock(mutex_);
    shared_.retrieve.reset();
    shared_.view.retrieving = false;
    ++shared_.view.retrieves;
    shared_.view.received = p.received;
    shared_.view.failed = p.failed;
    shared_.view.expected = p.expected;
    shared_.view.retrieveLine = line;
    shared_.log.push_back(line);
    shared_.audit.emplace_back(
        "retrieve",
        nlohmann::json{{"peer", name},
                       {"study", request.studyUid},
                       {"series", request.seriesUid},
                       {"method", how.method == net::RetrieveMethod::Move ? "move" : "get"},
                       {"received", p.received},
                       {"failed", p.failed},
                       {"expected", p.expected},
                       {"cancelled", outcome.cancelled},
                       {"problem", outcome.problem}});
}

void PacsClient::take(workflow::AuditLog& audit, std::ostream& err, const char* prefix) {
    std::vector<std::string> log;
    std::vector<std::pair<std::string, nlohmann::json>> records;
    {
        const std::lock_guard lock(mutex_);
        log.swap(shared_.log);
        records.swap(shared_.audit);
        shown_ = shared_.view;
    }
    for (const std::string& line : log) {
        err << prefix << line << '\n';
    }
    for (const auto& [event, fields] : records) {
        audit.pacs(event, fields);
    }
}

} // namespace steerseg::kiosk
