#pragma once

// Asking a PACS what it holds (C-FIND SCU, Study Root, DCMTK's dcmnet): the studies that match
// an operator's keys, and the series of one study. One association per question, over TLS
// where the peer has it; connection, negotiation and every response within the timeout, so a
// silent peer ends the question with a line saying so, never a hang.
#include "net/dicom_peer.hpp"
#include "net/scu_options.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::net {

// The keys of a study search; "" matches anything.
struct StudyQuery {
    std::string patientName; // PN, with * and ? as wildcards ("DOE*")
    std::string patientId;
    std::string studyDate; // YYYYMMDD or YYYYMMDD-YYYYMMDD
    std::string modality;  // one of the study's modalities (ModalitiesInStudy): "CT"
    std::string accession;
};

struct StudyMatch {
    std::string patientName; // as the PACS has it ("DOE^JANE"), printable ASCII only
    std::string patientId;
    std::string studyDate; // YYYYMMDD
    std::string studyTime;
    std::string description;
    std::string accession;
    std::string studyUid;
    std::string modalities; // "CT\MR"
    int seriesCount = -1;   // -1: the PACS did not say
    int instanceCount = -1;
};

struct SeriesMatch {
    std::string seriesUid;
    std::string modality;
    std::string number; // SeriesNumber as given
    std::string description;
    int instanceCount = -1;
};

// What a question brought: the matches in the PACS's order, whether more were cut off
// (`maxMatches`: the rest cancelled with C-CANCEL), and `problem`, one line, when it failed.
// A match whose UID (the study's, or the series') is missing or not a UID cannot be retrieved:
// it is left out, and `leftOut` says how many were, in one line ("" when none).
template <typename Match> struct QueryResult {
    std::vector<Match> matches;
    bool truncated = false;
    std::string leftOut;
    std::string problem;
};

// "" when `date` is YYYYMMDD or YYYYMMDD-YYYYMMDD of real calendar days, the range not
// backwards; else why not.
std::string studyDateProblem(std::string_view date);
// "" when every key is one the PACS can be sent (lengths, characters, the date); else the first
// key's problem, naming it.
std::string studyQueryProblem(const StudyQuery& query);

constexpr std::size_t kDefaultMaxMatches = 1000;

QueryResult<StudyMatch> findStudies(const DicomPeer& peer, const StudyQuery& query,
                                    const ScuOptions& options,
                                    std::size_t maxMatches = kDefaultMaxMatches);
// The series of the study `studyUid` (a UID: digits and dots).
QueryResult<SeriesMatch> findSeries(const DicomPeer& peer, const std::string& studyUid,
                                    const ScuOptions& options,
                                    std::size_t maxMatches = kDefaultMaxMatches);

} // namespace steerseg::net
