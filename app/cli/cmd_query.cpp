// `steerseg query`: asks a configured PACS (C-FIND, Study Root) which studies match, or which
// series a study has; one line per match on stdout, or a JSON array with --json.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/dicom_options.hpp"
#include "net/query_scu.hpp"
#include "net/store_scp.hpp" // isSafeUid

#include <cstdio>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

namespace steerseg::cli {
namespace {

const char* const kStudyKeys[] = {"patient-id", "patient-name", "study-date", "modality",
                                  "accession"};

nlohmann::json countOrNull(int n) {
    return n < 0 ? nlohmann::json(nullptr) : nlohmann::json(n);
}

std::vector<std::string> split(const std::string& values) {
    std::vector<std::string> parts;
    for (std::size_t at = 0; at <= values.size() && !values.empty();) {
        const std::size_t end = values.find('\\', at);
        parts.push_back(values.substr(at, end - at));
        at = end == std::string::npos ? values.size() + 1 : end + 1;
    }
    return parts;
}

std::string countText(int n, const char* what) {
    return n < 0 ? std::string("? ") + what : std::to_string(n) + " " + what;
}

// The parts that are there, joined by `separator`: a PACS leaves many keys empty.
std::string joined(std::initializer_list<std::string> parts, const char* separator) {
    std::string line;
    for (const std::string& part : parts) {
        if (!part.empty()) {
            line += (line.empty() ? "" : separator) + part;
        }
    }
    return line;
}

std::string dash(const std::string& text) {
    return text.empty() ? "-" : text;
}

template <typename Match>
void finish(const net::QueryResult<Match>& result, const std::string& peer,
            std::pair<const char*, const char*> what) {
    if (!result.problem.empty()) {
        throw std::runtime_error(result.problem);
    }
    std::fprintf(stderr, "%zu %s from %s%s\n", result.matches.size(),
                 result.matches.size() == 1 ? what.first : what.second, peer.c_str(),
                 result.truncated ? " (the first only; the rest cancelled: narrow the search)"
                                  : "");
    if (!result.leftOut.empty()) {
        std::fprintf(stderr, "%s\n", result.leftOut.c_str());
    }
}

void printStudies(const std::vector<net::StudyMatch>& studies, bool json) {
    if (json) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& s : studies) {
            list.push_back({{"patient_name", s.patientName},
                            {"patient_id", s.patientId},
                            {"study_date", s.studyDate},
                            {"study_time", s.studyTime},
                            {"description", s.description},
                            {"accession", s.accession},
                            {"study_uid", s.studyUid},
                            {"modalities", split(s.modalities)},
                            {"series", countOrNull(s.seriesCount)},
                            {"instances", countOrNull(s.instanceCount)}});
        }
        std::printf("%s\n", list.dump(2).c_str());
        return;
    }
    for (const auto& s : studies) {
        const std::string who = dash(s.patientName) + " (" + dash(s.patientId) + ")";
        const std::string line = joined(
            {dash(s.studyDate) + " " + dash(s.studyTime) + " " + dash(s.modalities) + " " + who,
             s.accession.empty() ? "" : "accession " + s.accession, s.description},
            ", ");
        std::printf("%s: %s, %s, study %s\n", line.c_str(),
                    countText(s.seriesCount, "series").c_str(),
                    countText(s.instanceCount, "images").c_str(), s.studyUid.c_str());
    }
}

void printSeries(const std::vector<net::SeriesMatch>& series, bool json) {
    if (json) {
        nlohmann::json list = nlohmann::json::array();
        for (const auto& s : series) {
            list.push_back({{"series_uid", s.seriesUid},
                            {"modality", s.modality},
                            {"number", s.number},
                            {"description", s.description},
                            {"instances", countOrNull(s.instanceCount)}});
        }
        std::printf("%s\n", list.dump(2).c_str());
        return;
    }
    for (const auto& s : series) {
        const std::string line =
            joined({dash(s.modality), s.number.empty() ? "" : "#" + s.number, s.description}, " ");
        std::printf("%s: %s, series %s\n", line.c_str(),
                    countText(s.instanceCount, "images").c_str(), s.seriesUid.c_str());
    }
}

} // namespace

int runQuery(std::span<const std::string> words) {
    const Args args(words,
                    {"to", "patient-id", "patient-name", "study-date", "modality", "accession",
                     "study", "config", "timeout"},
                    {"json"});
    if (!args.positional().empty()) {
        throw UsageError("unexpected '" + args.positional().front() + "'");
    }
    const config::KioskConfig cfg = nodeConfig(args);
    const kiosk::QueryPeer target = requireQueryPeer(args, cfg.dicom);
    net::ScuOptions options = kiosk::sendOptions(cfg.dicom);
    options.timeoutSeconds = scuTimeoutSeconds(args);
    const std::string peer = *args.value("to");
    if (const auto study = args.value("study")) {
        for (const char* key : kStudyKeys) {
            if (args.value(key)) {
                throw UsageError(std::string("--") + key +
                                 " searches studies; --study lists one study's series");
            }
        }
        if (!net::isSafeUid(*study)) {
            throw UsageError("--study: '" + *study + "' is not a UID (digits and dots)");
        }
        const auto result = net::findSeries(target.peer, *study, options);
        printSeries(result.matches, args.flag("json"));
        finish(result, peer, {"series", "series"});
        return kExitOk;
    }
    net::StudyQuery query;
    query.patientId = args.value("patient-id").value_or("");
    query.patientName = args.value("patient-name").value_or("");
    query.studyDate = args.value("study-date").value_or("");
    query.modality = args.value("modality").value_or("");
    query.accession = args.value("accession").value_or("");
    if (!query.studyDate.empty()) {
        if (const std::string problem = net::studyDateProblem(query.studyDate); !problem.empty()) {
            throw UsageError("--study-date: " + problem);
        }
    }
    if (const std::string problem = net::studyQueryProblem(query); !problem.empty()) {
        throw UsageError(problem);
    }
    const auto result = net::findStudies(target.peer, query, options);
    printStudies(result.matches, args.flag("json"));
    finish(result, peer, {"study", "studies"});
    return kExitOk;
}

} // namespace steerseg::cli
