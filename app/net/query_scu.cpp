// C-FIND through DcmSCU's own loop: the responses are read one at a time under the DIMSE
// timeout, each pending one turned into a match as it comes, the rest cancelled past the cap.
#include "net/query_scu.hpp"

#include "net/scu_association.hpp"
#include "net/store_scp.hpp" // isSafeUid

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <functional>

namespace steerseg::net {
namespace {

using Clock = std::chrono::steady_clock;

// What a peer may keep sending after a C-CANCEL before it is given up on (responses already
// on their way when the cancel went out).
constexpr std::size_t kAfterCancel = 1000;

bool digits(std::string_view text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool calendarDay(std::string_view yyyymmdd) {
    if (yyyymmdd.size() != 8 || !digits(yyyymmdd)) {
        return false;
    }
    const int y = std::stoi(std::string(yyyymmdd.substr(0, 4)));
    const unsigned m = static_cast<unsigned>(std::stoi(std::string(yyyymmdd.substr(4, 2))));
    const unsigned d = static_cast<unsigned>(std::stoi(std::string(yyyymmdd.substr(6, 2))));
    return std::chrono::year_month_day(std::chrono::year(y), std::chrono::month(m),
                                       std::chrono::day(d))
        .ok();
}

// A value the query may carry: printable ASCII within the VR's length, no backslash (it would
// make the key several values).
std::string valueProblem(std::string_view value, std::size_t maxLength) {
    if (value.size() > maxLength) {
        return "at most " + std::to_string(maxLength) + " characters";
    }
    if (std::any_of(value.begin(), value.end(), [](char c) { return c < ' ' || c > '~'; })) {
        return "printable ASCII characters only";
    }
    if (value.find('\\') != std::string_view::npos) {
        return "no backslash";
    }
    return "";
}

std::string modalityProblem(std::string_view value) {
    const bool ok =
        !value.empty() && value.size() <= 16 && std::all_of(value.begin(), value.end(), [](char c) {
            return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        });
    return ok ? "" : "1 to 16 of A-Z, 0-9 and _ (\"CT\", \"MR\")";
}

// Printable ASCII only: the values are the peer's, and go to a terminal or a screen.
std::string printable(const OFString& value) {
    std::string text = value.c_str();
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c < ' ' || c > '~'; }, '?');
    while (!text.empty() && text.back() == ' ') {
        text.pop_back();
    }
    return text;
}

std::string text(DcmDataset& d, const DcmTagKey& tag) {
    OFString value;
    d.findAndGetOFStringArray(tag, value); // every value: "CT\MR" for ModalitiesInStudy
    return printable(value);
}

int count(DcmDataset& d, const DcmTagKey& tag) {
    const std::string value = text(d, tag);
    const auto begin = value.find_first_not_of(' ');
    if (begin == std::string::npos || value.size() - begin > 9 ||
        !digits(std::string_view(value).substr(begin))) {
        return -1;
    }
    return std::stoi(value.substr(begin));
}

class FindScu : public PeerScu {
  public:
    FindScu(const DicomPeer& peer, const ScuOptions& options, std::size_t maxMatches,
            std::function<void(DcmDataset&)> onMatch)
        : PeerScu(peer, options), maxMatches_(maxMatches), onMatch_(std::move(onMatch)) {}

    bool truncated() const { return cancelled_; }
    bool abandoned() const { return abandoned_; }
    Uint16 finalStatus() const { return finalStatus_; }

  protected:
    OFCondition handleFINDResponse(const T_ASC_PresentationContextID presID, QRResponse* response,
                                   OFBool& waitForNext) override {
        waitForNext = OFFalse;
        if (response == nullptr) {
            return DIMSE_NULLKEY;
        }
        if (!DICOM_PENDING_STATUS(response->m_status)) {
            finalStatus_ = response->m_status;
            return EC_Normal;
        }
        waitForNext = OFTrue;
        if (cancelled_) {
            // Until the peer's final answer to the cancel, within bounds.
            if (++afterCancel_ > kAfterCancel ||
                Clock::now() - cancelledAt_ > std::chrono::seconds(options().timeoutSeconds)) {
                waitForNext = OFFalse;
                abandoned_ = true;
            }
            return EC_Normal;
        }
        if (response->m_dataset != nullptr) {
            onMatch_(*response->m_dataset);
        }
        if (++matches_ >= maxMatches_) {
            cancelled_ = true;
            cancelledAt_ = Clock::now();
            if (sendCANCELRequest(presID).bad()) {
                waitForNext = OFFalse;
                abandoned_ = true;
            }
        }
        return EC_Normal;
    }

  private:
    std::size_t maxMatches_;
    std::function<void(DcmDataset&)> onMatch_;
    std::size_t matches_ = 0;
    bool cancelled_ = false;
    bool abandoned_ = false;
    std::size_t afterCancel_ = 0;
    Clock::time_point cancelledAt_;
    Uint16 finalStatus_ = 0xFFFF;
};

// One C-FIND on its own association: "" or why it failed; each match handed to `onMatch`.
std::string find(const DicomPeer& peer, const ScuOptions& options, DcmDataset& keys,
                 std::size_t maxMatches, const std::function<void(DcmDataset&)>& onMatch,
                 bool& truncated) {
    FindScu scu(peer, options, std::max<std::size_t>(maxMatches, 1), onMatch);
    OFList<OFString> xfers;
    xfers.push_back(UID_LittleEndianExplicitTransferSyntax);
    xfers.push_back(UID_LittleEndianImplicitTransferSyntax);
    scu.addPresentationContext(UID_FINDStudyRootQueryRetrieveInformationModel, xfers);
    if (std::string problem = scu.associate(); !problem.empty()) {
        return problem;
    }
    const T_ASC_PresentationContextID id =
        scu.findAnyPresentationContextID(UID_FINDStudyRootQueryRetrieveInformationModel, "");
    if (id == 0) {
        scu.finish(true);
        return describe(peer) + " does not answer Study Root queries (C-FIND)";
    }
    const OFCondition c = scu.sendFINDRequest(id, &keys, nullptr);
    truncated = scu.truncated();
    const bool answered = c.good() && !scu.abandoned();
    scu.finish(answered);
    if (c.bad()) {
        return exchangeProblem(peer, "C-FIND", c, options.timeoutSeconds);
    }
    if (scu.abandoned()) {
        return describe(peer) + " went on answering after the query was cancelled";
    }
    const Uint16 status = scu.finalStatus();
    if (status != STATUS_Success &&
        !(truncated && status == STATUS_FIND_Cancel_MatchingTerminatedDueToCancelRequest)) {
        return statusProblem(peer, status);
    }
    return "";
}

void put(DcmDataset& keys, const DcmTagKey& tag, const std::string& value) {
    keys.putAndInsertOFStringArray(tag, value.c_str());
}

// Keeps `match` when its UID is one a retrieve can name; counts it into `leftOut` otherwise.
template <typename Match>
void keep(QueryResult<Match>& result, Match match, const std::string& uid, const char* what,
          int& unusable) {
    if (isSafeUid(uid)) {
        result.matches.push_back(std::move(match));
        return;
    }
    ++unusable;
    result.leftOut = std::to_string(unusable) + (unusable == 1 ? " answer" : " answers") +
                     " without a usable " + what + " UID left out (the PACS sent " +
                     (uid.empty() ? "none" : "'" + uid.substr(0, 64) + "'") + ")";
}

} // namespace

std::string studyDateProblem(std::string_view date) {
    const auto dash = date.find('-');
    const std::string_view from = date.substr(0, dash);
    const std::string_view to = dash == std::string_view::npos ? from : date.substr(dash + 1);
    if (!calendarDay(from) || !calendarDay(to)) {
        return "'" + std::string(date) +
               "' is not YYYYMMDD or YYYYMMDD-YYYYMMDD (a calendar day, e.g. 20240131)";
    }
    if (to < from) {
        return "'" + std::string(date) + "': the range ends before it begins";
    }
    return "";
}

std::string studyQueryProblem(const StudyQuery& query) {
    const struct {
        const char* key;
        const std::string& value;
        std::size_t maxLength;
    } values[] = {{"patient name", query.patientName, 64},
                  {"patient ID", query.patientId, 64},
                  {"accession number", query.accession, 16}};
    for (const auto& v : values) {
        if (std::string problem = valueProblem(v.value, v.maxLength); !problem.empty()) {
            return std::string(v.key) + ": " + problem;
        }
    }
    if (!query.modality.empty()) {
        if (std::string problem = modalityProblem(query.modality); !problem.empty()) {
            return "modality: " + problem;
        }
    }
    if (!query.studyDate.empty()) {
        if (std::string problem = studyDateProblem(query.studyDate); !problem.empty()) {
            return "study date: " + problem;
        }
    }
    return "";
}

QueryResult<StudyMatch> findStudies(const DicomPeer& peer, const StudyQuery& query,
                                    const ScuOptions& options, std::size_t maxMatches) {
    QueryResult<StudyMatch> result;
    if (std::string problem = studyQueryProblem(query); !problem.empty()) {
        result.problem = problem;
        return result;
    }
    DcmDataset keys;
    put(keys, DCM_QueryRetrieveLevel, "STUDY");
    put(keys, DCM_PatientName, query.patientName);
    put(keys, DCM_PatientID, query.patientId);
    put(keys, DCM_StudyDate, query.studyDate);
    put(keys, DCM_StudyTime, "");
    put(keys, DCM_StudyDescription, "");
    put(keys, DCM_AccessionNumber, query.accession);
    put(keys, DCM_StudyInstanceUID, "");
    put(keys, DCM_ModalitiesInStudy, query.modality);
    put(keys, DCM_NumberOfStudyRelatedSeries, "");
    put(keys, DCM_NumberOfStudyRelatedInstances, "");
    int unusable = 0;
    result.problem = find(
        peer, options, keys, maxMatches,
        [&](DcmDataset& d) {
            StudyMatch m;
            m.patientName = text(d, DCM_PatientName);
            m.patientId = text(d, DCM_PatientID);
            m.studyDate = text(d, DCM_StudyDate);
            m.studyTime = text(d, DCM_StudyTime);
            m.description = text(d, DCM_StudyDescription);
            m.accession = text(d, DCM_AccessionNumber);
            m.studyUid = text(d, DCM_StudyInstanceUID);
            m.modalities = text(d, DCM_ModalitiesInStudy);
            m.seriesCount = count(d, DCM_NumberOfStudyRelatedSeries);
            m.instanceCount = count(d, DCM_NumberOfStudyRelatedInstances);
            const std::string uid = m.studyUid;
            keep(result, std::move(m), uid, "Study Instance", unusable);
        },
        result.truncated);
    return result;
}

QueryResult<SeriesMatch> findSeries(const DicomPeer& peer, const std::string& studyUid,
                                    const ScuOptions& options, std::size_t maxMatches) {
    QueryResult<SeriesMatch> result;
    if (!isSafeUid(studyUid)) {
        result.problem = "study '" + studyUid + "' is not a UID (digits and dots, at most 64)";
        return result;
    }
    DcmDataset keys;
    put(keys, DCM_QueryRetrieveLevel, "SERIES");
    put(keys, DCM_StudyInstanceUID, studyUid);
    put(keys, DCM_SeriesInstanceUID, "");
    put(keys, DCM_Modality, "");
    put(keys, DCM_SeriesNumber, "");
    put(keys, DCM_SeriesDescription, "");
    put(keys, DCM_NumberOfSeriesRelatedInstances, "");
    int unusable = 0;
    result.problem = find(
        peer, options, keys, maxMatches,
        [&](DcmDataset& d) {
            SeriesMatch m;
            m.seriesUid = text(d, DCM_SeriesInstanceUID);
            m.modality = text(d, DCM_Modality);
            m.number = text(d, DCM_SeriesNumber);
            m.description = text(d, DCM_SeriesDescription);
            m.instanceCount = count(d, DCM_NumberOfSeriesRelatedInstances);
            const std::string uid = m.seriesUid;
            keep(result, std::move(m), uid, "Series Instance", unusable);
        },
        result.truncated);
    return result;
}

} // namespace steerseg::net
