// A DcmThreadSCP per association that files each C-STORE through the durable write path and
// keeps the node's rules: who may call, how much one association may bring, how much disk must
// stay free.
#include "net/store_association.hpp"

#include "exports/dicom_file_bytes.hpp"
#include "files/file_write.hpp"

#include <algorithm>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcxfer.h>
#include <dcmtk/dcmnet/scpthrd.h>
#include <memory>
#include <system_error>
#include <vector>

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

class StoreAssociation : public DcmThreadSCP {
  public:
    StoreAssociation(const ScpSettings& settings, StoreShared& shared)
        : settings_(settings), shared_(shared) {
        setAETitle(settings_.aet.c_str());
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

  protected:
    void notifyAssociationRequest(const T_ASC_Parameters& params,
                                  DcmSCPActionType& /*desiredAction*/) override {
        callingAet_ = params.DULparams.callingAPTitle;
        callingHost_ = params.DULparams.callingPresentationAddress;
    }

    // DcmSCP asks this after notifyAssociationRequest, so the caller's address is known here
    // too (its own host check is handed the called address, not the caller's).
    OFBool checkCallingAETitleAccepted(const OFString& callingAE) override {
        const auto& allowed = settings_.allowed;
        const bool ok = std::any_of(allowed.begin(), allowed.end(), [&](const AllowedCaller& a) {
            return a.aet == callingAE.c_str() && (a.host.empty() || a.host == callingHost_);
        });
        if (!ok) {
            const bool known = std::any_of(allowed.begin(), allowed.end(), [&](const auto& a) {
                return a.aet == callingAE.c_str();
            });
            shared_.report("rejected association from " + callingAet_ + " at " + callingHost_ +
                           (known ? ": calling AE title not allowed from this address"
                                  : ": calling AE title not allowed"));
        }
        return ok;
    }

    OFBool checkCalledAETitleAccepted(const OFString& calledAE) override {
        const bool ok = settings_.aet == calledAE.c_str();
        if (!ok) {
            shared_.report("rejected association from " + callingAet_ + " at " + callingHost_ +
                           ": called AE title '" + calledAE.c_str() + "' is not " + settings_.aet);
        }
        return ok;
    }

    OFCondition handleIncomingCommand(T_DIMSE_Message* message,
                                      const DcmPresentationContextInfo& info) override {
        if (message->CommandField == DIMSE_C_ECHO_RQ) {
            shared_.report("echo from " + callingAet_);
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

    void notifyAssociationTermination() override {
        if (stored_ > 0) {
            shared_.report("association from " + callingAet_ +
                           " ended: " + std::to_string(stored_) + " object(s) stored");
        }
    }

  private:
    OFCondition store(T_DIMSE_C_StoreRQ& request, const DcmPresentationContextInfo& info) {
        DcmDataset* received = nullptr;
        objectBytes_ = 0;
        const OFCondition c = receiveSTORERequest(request, info.presentationContextID, received);
        std::unique_ptr<DcmDataset> dataset(received);
        if (overQuota_) {
            shared_.report("aborted association from " + callingAet_ + ": more than " +
                           std::to_string(settings_.associationQuotaBytes >> 20) +
                           " MiB in one association");
            return DIMSE_RECEIVEFAILED;
        }
        if (c.bad()) {
            shared_.report("receive from " + callingAet_ + " failed: " + c.text());
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
            shared_.report("refused object" + from +
                           ": its SOP class or instance differs from the request's");
            return kDataSetMismatch;
        }
        if (!isSafeUid(study) || !isSafeUid(series) || !isSafeUid(sop)) {
            shared_.report("refused object" + from +
                           ": Study, Series or SOP Instance UID missing or not a UID");
            return kCannotUnderstand;
        }
        OFCondition c;
        DcmFileFormat fileFormat(dataset.release(), OFFalse);
        const E_TransferSyntax xfer = DcmXfer(info.acceptedTransferSyntax.c_str()).getXfer();
        // In 1 MiB passes: the object is in memory once already, its encoding once more.
        const std::vector<std::byte> bytes =
            exports::dicomFileBytes(fileFormat, xfer, std::size_t{1} << 20, c);
        if (c.bad()) {
            shared_.report("refused object" + from + ": cannot be encoded: " + c.text());
            return kCannotUnderstand;
        }
        // Before any folder is made: a refused object leaves no empty series behind.
        std::uint64_t available = 0;
        if (!shared_.reserve(settings_.store, bytes.size(), settings_.minFreeBytes, available)) {
            shared_.report("refused object" + from + ": the store has " +
                           std::to_string(available >> 20) +
                           " MiB free, less than the object and " +
                           std::to_string(settings_.minFreeBytes >> 20) + " MiB to keep");
            return kOutOfResources;
        }
        const Uint16 status = write(study, series, sop, bytes, from);
        shared_.release(bytes.size());
        return status;
    }

    // Another association may write into the same series at the same moment: the folders'
    // creation tolerates that, and each file has its own temporary name until its rename.
    Uint16 write(const std::string& study, const std::string& series, const std::string& sop,
                 const std::vector<std::byte>& bytes, const std::string& from) {
        const std::filesystem::path folder = settings_.store / study / series;
        std::error_code ec;
        std::filesystem::create_directories(folder, ec);
        try {
            files::writeFileAtomically(folder / (sop + ".dcm"),
                                       {std::span<const std::byte>(bytes)});
        } catch (const std::exception& e) {
            shared_.report("refused object" + from + ": " + e.what());
            return kOutOfResources;
        }
        ++stored_;
        shared_.report("stored " +
                       (std::filesystem::path(study) / series / (sop + ".dcm")).string() + from +
                       " (" + std::to_string(bytes.size()) + " bytes)");
        return kSuccess;
    }

    const ScpSettings& settings_;
    StoreShared& shared_;
    std::string callingAet_;
    std::string callingHost_;
    std::uint64_t associationBytes_ = 0;
    std::uint64_t objectBytes_ = 0;
    bool overQuota_ = false;
    int stored_ = 0;
};

} // namespace

void StoreShared::report(const std::string& line) {
    const std::lock_guard lock(reportMutex_);
    report_(line);
}

bool StoreShared::reserve(const std::filesystem::path& store, std::uint64_t bytes,
                          std::uint64_t minFree, std::uint64_t& available) {
    const std::lock_guard lock(spaceMutex_);
    std::error_code ec;
    const auto space = std::filesystem::space(store, ec);
    if (ec) {
        // Cannot tell: the write itself says whether the disk holds it.
        reserved_ += bytes;
        return true;
    }
    available = space.available > reserved_ ? space.available - reserved_ : 0;
    if (available < bytes + minFree) {
        return false;
    }
    reserved_ += bytes;
    return true;
}

void StoreShared::release(std::uint64_t bytes) {
    const std::lock_guard lock(spaceMutex_);
    reserved_ -= bytes;
}

void serveStoreAssociation(T_ASC_Association* assoc, const ScpSettings& settings,
                           StoreShared& shared) {
    StoreAssociation scp(settings, shared);
    // run() negotiates, serves the commands and drops and destroys the association; what went
    // wrong on the way is reported by the hooks above.
    (void)scp.run(assoc);
}

} // namespace steerseg::net
