// A DcmSCP that files each C-STORE through the durable write path and keeps its own rules: who
// may call, how much one association may bring, how much disk must stay free.
#include "net/store_scp.hpp"

#include "exports/dicom_file_bytes.hpp"
#include "files/file_write.hpp"
#include "net/dcmtk_quiet.hpp"
#include "net/store_retention.hpp"

#include <algorithm>
#include <chrono>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <dcmtk/dcmnet/dul.h>
#include <dcmtk/dcmnet/scp.h>
#include <system_error>

namespace steerseg::net {
namespace {

// What GDCM (scan/) reads: the uncompressed syntaxes, deflate, JPEG baseline, extended and
// lossless, JPEG-LS, JPEG 2000 and RLE. Uncompressed first, the SCP's preference.
const char* const kTransferSyntaxes[] = {
    UID_LittleEndianExplicitTransferSyntax, UID_LittleEndianImplicitTransferSyntax,
    UID_BigEndianExplicitTransferSyntax,    UID_DeflatedExplicitVRLittleEndianTransferSyntax,
    UID_JPEGProcess1TransferSyntax,         UID_JPEGProcess2_4TransferSyntax,
    UID_JPEGProcess14TransferSyntax,        UID_JPEGProcess14SV1TransferSyntax,
    UID_JPEGLSLosslessTransferSyntax,       UID_JPEGLSLossyTransferSyntax,
    UID_JPEG2000LosslessOnlyTransferSyntax, UID_JPEG2000TransferSyntax,
    UID_RLELosslessTransferSyntax,
};

// PS3.4 B.2.3 status codes the SCP answers with.
constexpr Uint16 kSuccess = 0x0000;
constexpr Uint16 kOutOfResources = 0xA700;
constexpr Uint16 kCannotUnderstand = 0xC000;
constexpr Uint16 kDataSetMismatch = 0xA900;

std::string text(const DcmDataset& dataset, const DcmTagKey& tag) {
    OFString value;
    const_cast<DcmDataset&>(dataset).findAndGetOFString(tag, value);
    return value.c_str();
}

} // namespace

bool isSafeUid(const std::string& uid) {
    return !uid.empty() && uid.size() <= 64 && uid.front() != '.' &&
           std::all_of(uid.begin(), uid.end(),
                       [](char c) { return (c >= '0' && c <= '9') || c == '.'; });
}

class StorageScp::Provider : public DcmSCP {
  public:
    Provider(ScpSettings settings, ScpReport report)
        : settings_(std::move(settings)), report_(std::move(report)) {
        setAETitle(settings_.aet.c_str());
        setPort(static_cast<Uint16>(settings_.port));
        // Polls for a stop request once a second between associations.
        setConnectionBlockingMode(DUL_NOBLOCK);
        setConnectionTimeout(1);
        setACSETimeout(static_cast<Uint32>(settings_.timeoutSeconds));
        setDIMSEBlockingMode(DIMSE_NONBLOCKING);
        setDIMSETimeout(static_cast<Uint32>(settings_.timeoutSeconds));
        setMaxReceivePDULength(ASC_DEFAULTMAXPDU);
        setHostLookupEnabled(OFFalse);
        setVerbosePCMode(OFFalse);
        OFList<OFString> xfers;
        for (const char* uid : kTransferSyntaxes) {
            xfers.push_back(uid);
        }
        for (int n = 0; n < numberOfDcmImageSOPClassUIDs; ++n) {
            addPresentationContext(dcmImageSOPClassUIDs[n], xfers);
        }
        OFList<OFString> echoXfers;
        echoXfers.push_back(UID_LittleEndianExplicitTransferSyntax);
        echoXfers.push_back(UID_LittleEndianImplicitTransferSyntax);
        addPresentationContext(UID_VerificationSOPClass, echoXfers);
    }

    void open() {
        std::error_code ec;
        std::filesystem::create_directories(settings_.store, ec);
        if (ec) {
            throw ScpError("cannot create the store " + settings_.store.string() + ": " +
                           ec.message());
        }
        prune();
        // openListenPort turns dcmdata's input data correction off for the whole process (to
        // see a peer's bytes as sent). The process's other DICOM readers need it on: without
        // it a UID keeps its NUL padding, and the kiosk's DICOM SEG of a scan read afterwards
        // fails its UID checks. The store's files are encoded anew either way.
        const OFBool correction = dcmEnableAutomaticInputDataCorrection.get();
        const OFCondition c = openListenPort();
        dcmEnableAutomaticInputDataCorrection.set(correction);
        if (c.bad()) {
            throw ScpError("cannot listen on port " + std::to_string(settings_.port) + ": " +
                           c.text());
        }
    }

    void serve(const std::atomic<bool>& stop) {
        stop_ = &stop;
        acceptAssociations();
        stop_ = nullptr;
    }

  protected:
    void notifyAssociationRequest(const T_ASC_Parameters& params,
                                  DcmSCPActionType& /*desiredAction*/) override {
        callingAet_ = params.DULparams.callingAPTitle;
        callingHost_ = params.DULparams.callingPresentationAddress;
        associationBytes_ = 0;
        objectBytes_ = 0;
        overQuota_ = false;
        stored_ = 0;
    }

    // DcmSCP asks this after notifyAssociationRequest, so the caller's address is known here
    // too (its own host check is handed the called address, not the caller's).
    OFBool checkCallingAETitleAccepted(const OFString& callingAE) override {
        const bool ok = std::any_of(
            settings_.allowed.begin(), settings_.allowed.end(), [&](const AllowedCaller& a) {
                return a.aet == callingAE.c_str() && (a.host.empty() || a.host == callingHost_);
            });
        if (!ok) {
            const bool known =
                std::any_of(settings_.allowed.begin(), settings_.allowed.end(),
                            [&](const AllowedCaller& a) { return a.aet == callingAE.c_str(); });
            report_("rejected association from " + callingAet_ + " at " + callingHost_ +
                    (known ? ": calling AE title not allowed from this address"
                           : ": calling AE title not allowed"));
        }
        return ok;
    }

    OFBool checkCalledAETitleAccepted(const OFString& calledAE) override {
        const bool ok = settings_.aet == calledAE.c_str();
        if (!ok) {
            report_("rejected association from " + callingAet_ + " at " + callingHost_ +
                    ": called AE title '" + calledAE.c_str() + "' is not " + settings_.aet);
        }
        return ok;
    }

    OFCondition handleIncomingCommand(T_DIMSE_Message* message,
                                      const DcmPresentationContextInfo& info) override {
        if (message->CommandField == DIMSE_C_ECHO_RQ) {
            report_("echo from " + callingAet_);
            return handleECHORequest(message->msg.CEchoRQ, info.presentationContextID);
        }
        if (message->CommandField == DIMSE_C_STORE_RQ) {
            return store(message->msg.CStoreRQ, info);
        }
        return DIMSE_BADCOMMANDTYPE;
    }

    // Each PDV of a data set: past the quota the association is aborted, so the rest of the
    // object is never read into memory.
    void notifyRECEIVEProgress(const unsigned long byteCount) override {
        objectBytes_ = byteCount;
        if (!overQuota_ && associationBytes_ + objectBytes_ > settings_.associationQuotaBytes) {
            overQuota_ = true;
            abortAssociation();
        }
    }

    // Once a second while no association is open: the hourly retention pass runs here.
    OFBool stopAfterConnectionTimeout() override {
        if (std::chrono::steady_clock::now() - lastPrune_ > std::chrono::hours(1)) {
            prune();
        }
        return stopRequested();
    }
    OFBool stopAfterCurrentAssociation() override { return stopRequested(); }

    void notifyAssociationTermination() override {
        if (stored_ > 0) {
            report_("association from " + callingAet_ + " ended: " + std::to_string(stored_) +
                    " object(s) stored");
        }
    }

  private:
    void prune() {
        lastPrune_ = std::chrono::steady_clock::now();
        if (settings_.keepDays <= 0) {
            return;
        }
        if (const int n = pruneStore(settings_.store, std::chrono::hours(24 * settings_.keepDays));
            n > 0) {
            report_("removed " + std::to_string(n) + " series older than " +
                    std::to_string(settings_.keepDays) + " day(s)");
        }
    }

    bool stopRequested() const { return stop_ != nullptr && stop_->load(); }

    OFCondition store(T_DIMSE_C_StoreRQ& request, const DcmPresentationContextInfo& info) {
        DcmDataset* received = nullptr;
        objectBytes_ = 0;
        const OFCondition c = receiveSTORERequest(request, info.presentationContextID, received);
        std::unique_ptr<DcmDataset> dataset(received);
        if (overQuota_) {
            report_("aborted association from " + callingAet_ + ": more than " +
                    std::to_string(settings_.associationQuotaBytes >> 20) +
                    " MiB in one association");
            return DIMSE_RECEIVEFAILED;
        }
        if (c.bad()) {
            report_("receive from " + callingAet_ + " failed: " + c.text());
            return c;
        }
        associationBytes_ += objectBytes_;
        const Uint16 status = file(request, dataset, info);
        return sendSTOREResponse(info.presentationContextID, request, status);
    }

    Uint16 file(const T_DIMSE_C_StoreRQ& request, std::unique_ptr<DcmDataset>& dataset,
                const DcmPresentationContextInfo& info) {
        const std::string study = text(*dataset, DCM_StudyInstanceUID);
        const std::string series = text(*dataset, DCM_SeriesInstanceUID);
        const std::string sop = text(*dataset, DCM_SOPInstanceUID);
        const std::string from = " from " + callingAet_;
        if (sop != request.AffectedSOPInstanceUID ||
            text(*dataset, DCM_SOPClassUID) != request.AffectedSOPClassUID) {
            report_("refused object" + from +
                    ": its SOP class or instance differs from the request's");
            return kDataSetMismatch;
        }
        if (!isSafeUid(study) || !isSafeUid(series) || !isSafeUid(sop)) {
            report_("refused object" + from +
                    ": Study, Series or SOP Instance UID missing or not a UID");
            return kCannotUnderstand;
        }
        const std::filesystem::path folder = settings_.store / study / series;
        const std::filesystem::path path = folder / (sop + ".dcm");
        OFCondition c;
        DcmFileFormat fileFormat(dataset.release(), OFFalse);
        const E_TransferSyntax xfer = DcmXfer(info.acceptedTransferSyntax.c_str()).getXfer();
        // In 1 MiB passes: the object is in memory once already, its encoding once more.
        const std::vector<std::byte> bytes =
            exports::dicomFileBytes(fileFormat, xfer, std::size_t{1} << 20, c);
        if (c.bad()) {
            report_("refused object" + from + ": cannot be encoded: " + c.text());
            return kCannotUnderstand;
        }
        // Before any folder is made: a refused object leaves no empty series behind.
        std::error_code ec;
        const auto space = std::filesystem::space(settings_.store, ec);
        if (!ec && space.available < bytes.size() + settings_.minFreeBytes) {
            report_("refused object" + from + ": the store has " +
                    std::to_string(space.available >> 20) + " MiB free, less than the object and " +
                    std::to_string(settings_.minFreeBytes >> 20) + " MiB to keep");
            return kOutOfResources;
        }
        std::filesystem::create_directories(folder, ec);
        try {
            files::writeFileAtomically(path, {std::span<const std::byte>(bytes)});
        } catch (const std::exception& e) {
            report_("refused object" + from + ": " + e.what());
            return kOutOfResources;
        }
        ++stored_;
        report_("stored " + (std::filesystem::path(study) / series / (sop + ".dcm")).string() +
                from + " (" + std::to_string(bytes.size()) + " bytes)");
        return kSuccess;
    }

    ScpSettings settings_;
    ScpReport report_;
    const std::atomic<bool>* stop_ = nullptr;
    std::string callingAet_;
    std::string callingHost_;
    std::uint64_t associationBytes_ = 0;
    std::uint64_t objectBytes_ = 0;
    bool overQuota_ = false;
    int stored_ = 0;
    std::chrono::steady_clock::time_point lastPrune_;
};

StorageScp::StorageScp(ScpSettings settings, ScpReport report) {
    quietDcmtk();
    // The caller's numeric address, as AllowedCaller::host names it, and no DNS wait.
    dcmDisableGethostbyaddr.set(OFTrue);
    provider_ = std::make_unique<Provider>(std::move(settings), std::move(report));
}

StorageScp::~StorageScp() = default;

void StorageScp::open() {
    provider_->open();
}

void StorageScp::serve(const std::atomic<bool>& stop) {
    provider_->serve(stop);
}

} // namespace steerseg::net
