// C-MOVE through DcmSCU's own loop with a hook per response; C-GET through a loop of its own,
// since DcmSCU's hands the C-STORE's data set on without its request (whose SOP class and
// instance the filing checks the data set against).
#include "net/retrieve_scu.hpp"

#include "net/scu_association.hpp"
#include "net/series_marks.hpp"
#include "net/store_filing.hpp"
#include "net/store_scp.hpp" // isSafeUid

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <memory>
#include <system_error>

namespace steerseg::net {
namespace {

using Clock = std::chrono::steady_clock;

class RetrieveScu : public PeerScu {
  public:
    RetrieveScu(const DicomPeer& peer, const ScuOptions& options, const RetrieveRequest& request,
                const RetrieveOptions& retrieve, const RetrieveReport& report,
                const RetrieveCancel& cancel)
        : PeerScu(peer, options), request_(request), report_(report), cancel_(cancel),
          shared_([this](const std::string& line) {
              if (line.rfind("refused", 0) == 0) {
                  lastRefusal_ = line;
              }
          }),
          marks_("a C-GET from " + describe(peer)),
          foreignMarks_("a C-GET from " + describe(peer) + " (not of the study asked for)"),
          target_{retrieve.store, retrieve.minFreeBytes, " from " + peer.aet, &marks_},
          foreignTarget_{retrieve.store, retrieve.minFreeBytes, " from " + peer.aet,
                         &foreignMarks_} {}

    // A C-GET that did not bring every image leaves its series marked incomplete. Images of
    // another study (or series) are a fragment of theirs whatever happened: marked always.
    void finishSeries(bool whole) {
        marks_.finish(whole);
        foreignMarks_.finish(false);
    }

    // The request's context, for the C-CANCEL.
    void setRequestContext(T_ASC_PresentationContextID id) { requestContext_ = id; }
    [[nodiscard]] const RetrieveProgress& progress() const { return progress_; }
    [[nodiscard]] bool cancelSent() const { return cancelSent_; }
    [[nodiscard]] bool abandoned() const { return abandoned_; }
    [[nodiscard]] bool answered() const { return answered_; }
    [[nodiscard]] Uint16 finalStatus() const { return finalStatus_; }
    [[nodiscard]] const std::string& lastRefusal() const { return lastRefusal_; }
    [[nodiscard]] int foreign() const { return foreign_; }
    [[nodiscard]] const std::string& foreignWhat() const { return foreignWhat_; }

  protected:
    OFCondition handleMOVEResponse(const T_ASC_PresentationContextID /*presID*/,
                                   RetrieveResponse* response, OFBool& waitForNext) override {
        waitForNext = OFFalse;
        if (response == nullptr) {
            return DIMSE_NULLKEY;
        }
        // The images are the Storage SCP's: the PACS's count is all there is to go by.
        count(response->m_numberOfCompletedSubops + response->m_numberOfWarningSubops,
              response->m_numberOfCompletedSubops, response->m_numberOfFailedSubops,
              response->m_numberOfWarningSubops, response->m_numberOfRemainingSubops);
        if (!DICOM_PENDING_STATUS(response->m_status)) {
            answer(response->m_status);
            return EC_Normal;
        }
        waitForNext = keepWaiting() ? OFTrue : OFFalse;
        return EC_Normal;
    }

    OFCondition handleCGETSession(const T_ASC_PresentationContextID /*presID*/,
                                  DcmDataset* /*dataset*/,
                                  OFList<RetrieveResponse*>* /*responses*/) override {
        while (true) {
            T_DIMSE_Message message;
            std::memset(&message, 0, sizeof message);
            T_ASC_PresentationContextID id = 0;
            DcmDataset* detail = nullptr;
            OFCondition c = receiveDIMSECommand(&id, &message, &detail);
            delete detail;
            if (c.bad()) {
                return c;
            }
            if (message.CommandField == DIMSE_C_STORE_RQ) {
                if (c = storeOne(id, message.msg.CStoreRQ); c.bad()) {
                    return c;
                }
            } else if (message.CommandField == DIMSE_C_GET_RSP) {
                const T_DIMSE_C_GetRSP& r = message.msg.CGetRSP;
                if (r.DataSetType != DIMSE_DATASET_NULL) {
                    // The failed instances' list: the counts say as much.
                    DcmDataset* failed = nullptr;
                    c = receiveDIMSEDataset(&id, &failed);
                    delete failed;
                    if (c.bad()) {
                        return c;
                    }
                }
                count(filed_, r.NumberOfCompletedSubOperations, r.NumberOfFailedSubOperations,
                      r.NumberOfWarningSubOperations, r.NumberOfRemainingSubOperations);
                if (!DICOM_PENDING_STATUS(r.DimseStatus)) {
                    answer(r.DimseStatus);
                    return EC_Normal;
                }
                if (!keepWaiting()) {
                    return EC_Normal;
                }
            } else {
                return DIMSE_BADCOMMANDTYPE;
            }
        }
    }

  private:
    // One image of the C-GET, filed as the Storage SCP files a pushed one, then answered.
    OFCondition storeOne(T_ASC_PresentationContextID id, const T_DIMSE_C_StoreRQ& request) {
        DcmDataset* received = nullptr;
        const OFCondition c = receiveDIMSEDataset(&id, &received);
        if (c.bad()) {
            delete received;
            return c;
        }
        OFString sopClass;
        OFString xfer;
        findPresentationContext(id, sopClass, xfer);
        // Kept (nothing that arrived is lost) but apart from what was asked for: another
        // patient's image must not make the study asked for look whole.
        const std::string stranger = notAskedFor(*received);
        const Uint16 status =
            fileObject(std::unique_ptr<DcmDataset>(received), request.AffectedSOPClassUID,
                       request.AffectedSOPInstanceUID, xfer.c_str(),
                       stranger.empty() ? target_ : foreignTarget_, shared_);
        if (status != STATUS_Success) {
            ++refused_;
        } else if (stranger.empty()) {
            ++filed_;
        } else if (++foreign_ == 1) {
            foreignWhat_ = stranger;
        }
        count(filed_, 0, 0, 0, 0);
        // Before the answer: a PACS checks for a cancel before its next image.
        const bool going = keepWaiting();
        const OFCondition answer = sendSTOREResponse(id, status, request);
        if (answer.bad()) {
            return answer;
        }
        return going ? EC_Normal : DIMSE_NODATAAVAILABLE;
    }

    // "" when the data set is of the study (and series) asked for; else whose it is.
    std::string notAskedFor(DcmDataset& d) const {
        OFString study;
        OFString series;
        d.findAndGetOFString(DCM_StudyInstanceUID, study);
        d.findAndGetOFString(DCM_SeriesInstanceUID, series);
        const auto shown = [](const OFString& uid) {
            std::string text = uid.c_str();
            if (!isSafeUid(text)) {
                text = "(not a UID)";
            }
            return text;
        };
        if (request_.studyUid != study.c_str()) {
            return "study " + shown(study);
        }
        if (!request_.seriesUid.empty() && request_.seriesUid != series.c_str()) {
            return "series " + shown(series);
        }
        return "";
    }

    // Reported when it changed. `expected` only from the PACS's counts: a C-GET's first image
    // may come before the first response that says how many follow.
    void count(int received, int completed, int failed, int warning, int remaining) {
        const RetrieveProgress before = progress_;
        progress_.received = std::max(progress_.received, received);
        progress_.failed = std::max({progress_.failed, failed, refused_});
        const int said = completed + failed + warning + remaining;
        if (said > 0) {
            progress_.expected = std::max({progress_.expected, said, progress_.received});
        }
        const bool changed = progress_.received != before.received ||
                             progress_.failed != before.failed ||
                             progress_.expected != before.expected;
        if (changed && report_) {
            report_(progress_);
        }
    }

    void answer(Uint16 status) {
        answered_ = true;
        finalStatus_ = status;
    }

    // Asks the cancel between responses; false once a cancelled PACS has had the timeout to
    // end it (or the cancel could not be sent).
    bool keepWaiting() {
        if (!cancelSent_ && cancel_ && cancel_()) {
            cancelSent_ = true;
            cancelledAt_ = Clock::now();
            if (sendCANCELRequest(requestContext_).bad()) {
                abandoned_ = true;
                return false;
            }
        }
        if (cancelSent_ &&
            Clock::now() - cancelledAt_ > std::chrono::seconds(options().timeoutSeconds)) {
            abandoned_ = true;
            return false;
        }
        return true;
    }

    const RetrieveRequest& request_;
    const RetrieveReport& report_;
    const RetrieveCancel& cancel_;
    StoreShared shared_;
    SeriesMarks marks_;
    SeriesMarks foreignMarks_;
    FilingTarget target_;
    FilingTarget foreignTarget_;
    std::string lastRefusal_;
    std::string foreignWhat_;
    int foreign_ = 0;
    T_ASC_PresentationContextID requestContext_ = 0;
    RetrieveProgress progress_;
    int filed_ = 0;
    int refused_ = 0;
    bool cancelSent_ = false;
    bool abandoned_ = false;
    bool answered_ = false;
    Uint16 finalStatus_ = 0xFFFF;
    Clock::time_point cancelledAt_;
};

OFList<OFString> uncompressed() {
    OFList<OFString> xfers;
    xfers.push_back(UID_LittleEndianExplicitTransferSyntax);
    xfers.push_back(UID_LittleEndianImplicitTransferSyntax);
    return xfers;
}

// What the PACS's last answer means for the operator: "" when every image came.
std::string outcomeProblem(const RetrieveScu& scu, const DicomPeer& peer,
                           const RetrieveOptions& options, bool& cancelled) {
    const RetrieveProgress& p = scu.progress();
    const std::string images =
        std::to_string(p.received) + " of " + std::to_string(p.expected) + " image(s)";
    const Uint16 status = scu.finalStatus();
    if (status == STATUS_GET_Cancel) {
        cancelled = true;
        return "cancelled after " + images;
    }
    if (status == STATUS_Success ||
        status == STATUS_GET_Warning_SubOperationsCompleteOneOrMoreFailures) {
        if (p.received == 0 && p.failed == 0) {
            return describe(peer) + " has no image of it (nothing matched)";
        }
        if (p.failed == 0 && p.received >= p.expected) {
            return "";
        }
        return describe(peer) + " sent " + images + ", " + std::to_string(p.failed) + " failed" +
               (scu.lastRefusal().empty() ? "" : " (last: " + scu.lastRefusal() + ")");
    }
    if (status == 0xA801) { // C-MOVE's own failure: the PACS does not know where to send
        return describe(peer) + " answered 0xA801 (move destination unknown: the PACS needs " +
               options.moveDestination +
               " among its DICOM modalities, with this node's host and port)";
    }
    return statusProblem(peer, status) + (p.received + p.failed > 0 ? " after " + images : "");
}

} // namespace

std::string retrieveRequestProblem(const RetrieveRequest& request) {
    if (!isSafeUid(request.studyUid)) {
        return "study '" + request.studyUid + "' is not a UID (digits and dots, at most 64)";
    }
    if (!request.seriesUid.empty() && !isSafeUid(request.seriesUid)) {
        return "series '" + request.seriesUid + "' is not a UID (digits and dots, at most 64)";
    }
    return "";
}

RetrieveOutcome retrieve(const DicomPeer& peer, const RetrieveRequest& request,
                         const RetrieveOptions& retrieveOptions, const ScuOptions& options,
                         const RetrieveReport& report, const RetrieveCancel& cancel) {
    RetrieveOutcome outcome;
    if (outcome.problem = retrieveRequestProblem(request); !outcome.problem.empty()) {
        return outcome;
    }
    const bool get = retrieveOptions.method == RetrieveMethod::Get;
    if (get) {
        std::error_code ec;
        std::filesystem::create_directories(retrieveOptions.store, ec);
        if (ec) {
            outcome.problem =
                "cannot create the store " + retrieveOptions.store.string() + ": " + ec.message();
            return outcome;
        }
    }
    const char* model = get ? UID_GETStudyRootQueryRetrieveInformationModel
                            : UID_MOVEStudyRootQueryRetrieveInformationModel;
    RetrieveScu scu(peer, options, request, retrieveOptions, report, cancel);
    scu.addPresentationContext(model, uncompressed());
    if (get) {
        // The images come as C-STOREs on this association: this side is their Storage SCP, for
        // what the node takes when it receives.
        OFList<OFString> xfers;
        for (const char* uid : acceptedTransferSyntaxes()) {
            xfers.push_back(uid);
        }
        for (const char* sopClass : acceptedImageSopClasses()) {
            scu.addPresentationContext(sopClass, xfers, ASC_SC_ROLE_SCP);
        }
    }
    if (outcome.problem = scu.associate(); !outcome.problem.empty()) {
        return outcome;
    }
    const T_ASC_PresentationContextID id = scu.findAnyPresentationContextID(model, "");
    if (id == 0) {
        scu.finish(true);
        outcome.problem = describe(peer) + " does not take Study Root " +
                          (get ? "C-GET" : "C-MOVE") + " requests";
        return outcome;
    }
    scu.setRequestContext(id);
    DcmDataset keys;
    keys.putAndInsertOFStringArray(DCM_QueryRetrieveLevel,
                                   request.seriesUid.empty() ? "STUDY" : "SERIES");
    keys.putAndInsertOFStringArray(DCM_StudyInstanceUID, request.studyUid.c_str());
    if (!request.seriesUid.empty()) {
        keys.putAndInsertOFStringArray(DCM_SeriesInstanceUID, request.seriesUid.c_str());
    }
    const OFCondition c =
        get ? scu.sendCGETRequest(id, &keys, nullptr)
            : scu.sendMOVERequest(id, retrieveOptions.moveDestination.c_str(), &keys, nullptr);
    outcome.progress = scu.progress();
    const bool answered = c.good() && scu.answered() && !scu.abandoned();
    scu.finish(answered);
    if (scu.abandoned()) {
        outcome.cancelled = true;
        outcome.problem = describe(peer) + " did not end the retrieve within " +
                          std::to_string(options.timeoutSeconds) + " s of the cancel (after " +
                          std::to_string(outcome.progress.received) + " image(s)); aborted";
    } else if (c.bad() || !scu.answered()) {
        outcome.problem =
            exchangeProblem(peer, get ? "C-GET" : "C-MOVE", c, options.timeoutSeconds);
    } else {
        outcome.problem = outcomeProblem(scu, peer, retrieveOptions, outcome.cancelled);
    }
    scu.finishSeries(outcome.problem.empty() && !outcome.cancelled);
    if (scu.foreign() > 0) {
        const std::string line = describe(peer) + " also sent " + std::to_string(scu.foreign()) +
                                 " image(s) not of the " +
                                 (request.seriesUid.empty() ? "study" : "series") +
                                 " asked for (the first of " + scu.foreignWhat() +
                                 "): kept in the store apart from it, listed as incomplete";
        outcome.problem = outcome.problem.empty() ? line : outcome.problem + "; " + line;
    }
    return outcome;
}

} // namespace steerseg::net
