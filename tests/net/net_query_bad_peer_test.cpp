// Query/retrieve against a PACS that answers wrongly, which Orthanc cannot be made to do: a
// DCMTK DcmSCP on a loopback port whose C-FIND answers lack or garble their attributes, and whose
// C-GET brings an image of another study or stops half way (the association aborted). Nothing
// that arrived is lost, nothing is listed whole that is not, and each says so in a line.
#include "net/net_harness.hpp"
#include "net/query_scu.hpp"
#include "net/received_series.hpp"
#include "net/retrieve_scu.hpp"

#include <atomic>
#include <cstring>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scp.h>
#include <gtest/gtest.h>
#include <stdexcept>
#include <thread>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

enum class Misdeed { GarbledAnswers, ImageOfAnotherStudy, StopsHalfWay };

std::string newUid() {
    char uid[100];
    return dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT);
}

// A small CT image of `study`/`series`.
std::unique_ptr<DcmDataset> image(const std::string& study, const std::string& series,
                                  const std::string& sop) {
    auto d = std::make_unique<DcmDataset>();
    d->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
    d->putAndInsertString(DCM_SOPInstanceUID, sop.c_str());
    d->putAndInsertString(DCM_StudyInstanceUID, study.c_str());
    d->putAndInsertString(DCM_SeriesInstanceUID, series.c_str());
    d->putAndInsertString(DCM_PatientName, "BAD^PEER");
    d->putAndInsertString(DCM_Modality, "CT");
    d->putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
    d->putAndInsertUint16(DCM_SamplesPerPixel, 1);
    d->putAndInsertUint16(DCM_Rows, 4);
    d->putAndInsertUint16(DCM_Columns, 4);
    d->putAndInsertUint16(DCM_BitsAllocated, 16);
    d->putAndInsertUint16(DCM_BitsStored, 16);
    d->putAndInsertUint16(DCM_HighBit, 15);
    d->putAndInsertUint16(DCM_PixelRepresentation, 0);
    const std::vector<Uint16> pixels(16, 7);
    d->putAndInsertUint16Array(DCM_PixelData, pixels.data(), pixels.size());
    return d;
}

class MisbehavingPacs : public DcmSCP {
  public:
    MisbehavingPacs(Misdeed misdeed, std::string study, std::string series, std::string other)
        : misdeed_(misdeed), study_(std::move(study)), series_(std::move(series)),
          other_(std::move(other)), port_(freePort()) {
        setPort(static_cast<Uint16>(port_));
        setAETitle("BADPACS");
        setConnectionBlockingMode(DUL_NOBLOCK);
        setConnectionTimeout(1); // so that the destructor's stop is seen within a second
        setACSETimeout(5);
        setDIMSETimeout(5);
        OFList<OFString> xfers;
        xfers.push_back(UID_LittleEndianExplicitTransferSyntax);
        xfers.push_back(UID_LittleEndianImplicitTransferSyntax);
        addPresentationContext(UID_FINDStudyRootQueryRetrieveInformationModel, xfers);
        addPresentationContext(UID_GETStudyRootQueryRetrieveInformationModel, xfers);
        // The requestor of a C-GET plays the Storage SCP for the images that come back.
        addPresentationContext(UID_CTImageStorage, xfers, ASC_SC_ROLE_SCP);
        // Listening before the constructor returns: a client of the test must not race the
        // thread to the port.
        if (openListenPort().bad()) {
            throw std::runtime_error("the misbehaving PACS cannot listen on port " +
                                     std::to_string(port_));
        }
        thread_ = std::thread([this] { acceptAssociations(); });
    }
    ~MisbehavingPacs() override {
        stop_ = true;
        thread_.join();
    }
    MisbehavingPacs(const MisbehavingPacs&) = delete;
    MisbehavingPacs& operator=(const MisbehavingPacs&) = delete;

    [[nodiscard]] net::DicomPeer peer() const { return {"BADPACS", "127.0.0.1", port_, false}; }

  protected:
    OFBool stopAfterConnectionTimeout() override { return stop_ ? OFTrue : OFFalse; }
    OFBool stopAfterCurrentAssociation() override { return stop_ ? OFTrue : OFFalse; }

    OFCondition handleIncomingCommand(T_DIMSE_Message* message,
                                      const DcmPresentationContextInfo& info) override {
        if (message->CommandField == DIMSE_C_FIND_RQ) {
            return answerFind(message->msg.CFindRQ, info.presentationContextID);
        }
        if (message->CommandField == DIMSE_C_GET_RQ) {
            return answerGet(message->msg.CGetRQ, info.presentationContextID);
        }
        return DcmSCP::handleIncomingCommand(message, info);
    }

  private:
    // One usable study, one with no Study Instance UID, one whose UID is no UID, one with
    // garbled counts and control characters in its name: the search must keep the usable ones.
    OFCondition answerFind(T_DIMSE_C_FindRQ& request, T_ASC_PresentationContextID id) {
        DcmDataset* keys = nullptr;
        OFCondition c = receiveFINDRequest(request, id, keys);
        delete keys;
        if (c.bad()) {
            return c;
        }
        const struct {
            const char* uid;
            const char* name;
            const char* series;
        } answers[] = {{study_.c_str(), "GOOD^ONE", "2"},
                       {nullptr, "NO^UID", "1"},
                       {"1.2.x/../y", "BAD^UID", "1"},
                       {other_.c_str(), "CTRL\x01\x1b[2J^NAME", "many"}};
        for (const auto& a : answers) {
            DcmDataset match;
            match.putAndInsertString(DCM_QueryRetrieveLevel, "STUDY");
            match.putAndInsertString(DCM_PatientName, a.name);
            if (a.uid != nullptr) {
                match.putAndInsertString(DCM_StudyInstanceUID, a.uid, OFFalse);
            }
            match.putAndInsertString(DCM_NumberOfStudyRelatedSeries, a.series, OFFalse);
            if (c = sendFINDResponse(id, request.MessageID, request.AffectedSOPClassUID, &match,
                                     STATUS_Pending);
                c.bad()) {
                return c;
            }
        }
        return sendFINDResponse(id, request.MessageID, request.AffectedSOPClassUID, nullptr,
                                STATUS_Success);
    }

    OFCondition answerGet(T_DIMSE_C_GetRQ& request, T_ASC_PresentationContextID id) {
        DcmDataset* keys = nullptr;
        OFCondition c = receiveDIMSEDataset(&id, &keys);
        delete keys;
        if (c.bad()) {
            return c;
        }
        const T_ASC_PresentationContextID storeId = ctContext();
        const bool halfWay = misdeed_ == Misdeed::StopsHalfWay;
        // Two of the study asked for, then (the misdeed) one of another study or the abort.
        const int total = 3;
        for (int n = 0; n < total; ++n) {
            if (halfWay && n == 1) {
                return abortAssociation();
            }
            const bool stranger = n == 2;
            const std::string sop = newUid();
            auto d = image(stranger ? other_ : study_, stranger ? newUid() : series_, sop);
            if (c = storeSubOperation(storeId, sop, *d); c.bad()) {
                return c;
            }
            if (c = getResponse(id, request, STATUS_Pending, n + 1, total - n - 1); c.bad()) {
                return c;
            }
        }
        return getResponse(id, request, STATUS_Success, total, 0);
    }

    // The accepted context for CT Image Storage that the requestor proposed.
    T_ASC_PresentationContextID ctContext() {
        for (int id = 1; id < 256; id += 2) {
            OFString abstract;
            OFString xfer;
            findPresentationContext(static_cast<T_ASC_PresentationContextID>(id), abstract, xfer);
            if (abstract == UID_CTImageStorage && !xfer.empty()) {
                return static_cast<T_ASC_PresentationContextID>(id);
            }
        }
        return 0;
    }

    OFCondition storeSubOperation(T_ASC_PresentationContextID id, const std::string& sop,
                                  DcmDataset& d) {
        T_DIMSE_Message store;
        std::memset(&store, 0, sizeof store);
        store.CommandField = DIMSE_C_STORE_RQ;
        T_DIMSE_C_StoreRQ& rq = store.msg.CStoreRQ;
        rq.MessageID = ++messageId_;
        OFStandard::strlcpy(rq.AffectedSOPClassUID, UID_CTImageStorage,
                            sizeof rq.AffectedSOPClassUID);
        OFStandard::strlcpy(rq.AffectedSOPInstanceUID, sop.c_str(),
                            sizeof rq.AffectedSOPInstanceUID);
        rq.Priority = DIMSE_PRIORITY_MEDIUM;
        rq.DataSetType = DIMSE_DATASET_PRESENT;
        if (OFCondition c = sendDIMSEMessage(id, &store, &d); c.bad()) {
            return c;
        }
        T_DIMSE_Message answer;
        std::memset(&answer, 0, sizeof answer);
        T_ASC_PresentationContextID answerId = 0;
        DcmDataset* detail = nullptr;
        const OFCondition c = receiveDIMSECommand(&answerId, &answer, &detail);
        delete detail;
        return c;
    }

    OFCondition getResponse(T_ASC_PresentationContextID id, const T_DIMSE_C_GetRQ& request,
                            Uint16 status, int completed, int remaining) {
        T_DIMSE_Message rsp;
        std::memset(&rsp, 0, sizeof rsp);
        rsp.CommandField = DIMSE_C_GET_RSP;
        T_DIMSE_C_GetRSP& r = rsp.msg.CGetRSP;
        r.MessageIDBeingRespondedTo = request.MessageID;
        OFStandard::strlcpy(r.AffectedSOPClassUID, request.AffectedSOPClassUID,
                            sizeof r.AffectedSOPClassUID);
        r.DimseStatus = status;
        r.DataSetType = DIMSE_DATASET_NULL;
        r.NumberOfCompletedSubOperations = static_cast<Uint16>(completed);
        r.NumberOfRemainingSubOperations = static_cast<Uint16>(remaining);
        r.opts = O_GET_AFFECTEDSOPCLASSUID | O_GET_NUMBEROFREMAININGSUBOPERATIONS |
                 O_GET_NUMBEROFCOMPLETEDSUBOPERATIONS | O_GET_NUMBEROFFAILEDSUBOPERATIONS |
                 O_GET_NUMBEROFWARNINGSUBOPERATIONS;
        return sendDIMSEMessage(id, &rsp, nullptr);
    }

    Misdeed misdeed_;
    std::string study_;
    std::string series_;
    std::string other_;
    int port_;
    Uint16 messageId_ = 100;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

net::ScuOptions quick() {
    net::ScuOptions options;
    options.timeoutSeconds = 5;
    return options;
}

TEST(NetQueryBadPeer, AnswersWithoutAUsableUidAreLeftOutAndSaidSo) {
    const std::string study = newUid();
    const std::string other = newUid();
    const MisbehavingPacs pacs(Misdeed::GarbledAnswers, study, newUid(), other);
    const auto found = net::findStudies(pacs.peer(), {}, quick());
    ASSERT_EQ(found.problem, "");
    ASSERT_EQ(found.matches.size(), 2U);
    EXPECT_EQ(found.matches[0].studyUid, study);
    EXPECT_EQ(found.matches[0].seriesCount, 2);
    EXPECT_EQ(found.matches[1].studyUid, other);
    EXPECT_EQ(found.matches[1].seriesCount, -1) << "'many' is no count";
    EXPECT_EQ(found.matches[1].patientName.find_first_of("\x01\x1b"), std::string::npos)
        << "a peer's control characters never reach a screen";
    EXPECT_NE(found.leftOut.find("2 answers without a usable Study Instance UID left out"),
              std::string::npos)
        << found.leftOut;
}

TEST(NetQueryBadPeer, AnImageOfAnotherStudyIsKeptApartAndTheRetrieveSaysSo) {
    const std::string study = newUid();
    const std::string series = newUid();
    const std::string other = newUid();
    const MisbehavingPacs pacs(Misdeed::ImageOfAnotherStudy, study, series, other);
    const fs::path store = tempDir("net-query-bad-peer-foreign") / "store";
    net::RetrieveOptions how;
    how.store = store;
    const auto got = net::retrieve(pacs.peer(), {study, ""}, how, quick());
    EXPECT_EQ(got.progress.received, 2) << "the stranger is not counted as the study's";
    EXPECT_NE(got.problem.find("also sent 1 image(s) not of the study asked for (the first of "
                               "study " +
                               other + ")"),
              std::string::npos)
        << got.problem;
    bool sawOwn = false;
    bool sawStranger = false;
    for (const auto& s : net::listReceivedSeries(store, std::chrono::seconds(0))) {
        const std::string owner = s.folder.parent_path().filename().string();
        if (owner == other) {
            sawStranger = true;
            EXPECT_EQ(s.images, 1) << "nothing that arrived is lost";
            EXPECT_TRUE(s.incomplete) << "another study's fragment is never listed whole";
        } else {
            sawOwn = true;
            EXPECT_EQ(owner, study);
            EXPECT_EQ(s.images, 2);
            // The PACS counted the stranger among the study's images: two of three came.
            EXPECT_TRUE(s.incomplete);
        }
    }
    EXPECT_TRUE(sawOwn);
    EXPECT_TRUE(sawStranger);
}

TEST(NetQueryBadPeer, ARetrieveCutOffHalfWayKeepsWhatCameAsIncomplete) {
    const std::string study = newUid();
    const std::string series = newUid();
    const MisbehavingPacs pacs(Misdeed::StopsHalfWay, study, series, newUid());
    const fs::path store = tempDir("net-query-bad-peer-halfway") / "store";
    net::RetrieveOptions how;
    how.store = store;
    const auto got = net::retrieve(pacs.peer(), {study, series}, how, quick());
    EXPECT_FALSE(got.problem.empty());
    EXPECT_NE(got.problem.find("BADPACS@127.0.0.1"), std::string::npos) << got.problem;
    EXPECT_EQ(got.progress.received, 1);
    EXPECT_EQ(got.progress.expected, 3);
    const auto listed = net::listReceivedSeries(store, std::chrono::seconds(0));
    ASSERT_EQ(listed.size(), 1U);
    EXPECT_EQ(listed[0].folder, store / study / series);
    EXPECT_EQ(listed[0].images, 1);
    EXPECT_TRUE(listed[0].incomplete) << net::describe(listed[0]);
}

} // namespace
} // namespace steerseg::test
