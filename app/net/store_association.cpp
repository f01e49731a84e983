// A DcmThreadSCP per association that files each C-STORE (store_filing) and keeps the node's
// rules: who may call, how much one association may bring, how much disk must stay free.
#include "net/store_association.hpp"

#include "net/series_marks.hpp"

#include <algorithm>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmnet/scpthrd.h>
#include <memory>
#include <optional>

namespace steerseg::net {
namespace {

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
        for (const char* uid : acceptedTransferSyntaxes()) {
            xfers.push_back(uid);
        }
        for (const char* sopClass : acceptedImageSopClasses()) {
            addPresentationContext(sopClass, xfers);
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
        marks_.emplace(callingAet_ + " at " + callingHost_);
    }

    // DcmSCP calls this before it acknowledges the release: a series whole at the release is
    // unmarked here, so that a sender whose release is done finds it listed whole at once.
    void notifyReleaseRequest() override {
        released_ = true;
        if (marks_ && failed_ == 0 && !overQuota_) {
            marks_->finish(true);
        }
    }
    // DCMTK says so for an A-ABORT and for a connection closed or reset under it alike.
    void notifyAbortRequest() override {
        ending_ = "aborted by the sender, or its connection closed";
    }
    void notifyConnectionTimeout() override {
        ending_ =
            "nothing from the sender within " + std::to_string(settings_.timeoutSeconds) + " s";
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

  public:
    // After run(): the series this association wrote into are whole, or marked incomplete and
    // said so, one line each.
    void finishSeries() {
        if (!marks_) {
            return;
        }
        const bool whole = released_ && failed_ == 0 && !overQuota_;
        for (const auto& folder : marks_->finish(whole)) {
            if (whole) {
                continue;
            }
            const std::string why =
                overQuota_           ? "the association was aborted past its quota"
                : released_          ? std::to_string(failed_) + " object(s) refused"
                : shared_.stopping() ? "the node stopped before the association's release"
                                     : "the association ended before its release (" + ending_ + ")";
            shared_.report("incomplete series " +
                           folder.lexically_relative(settings_.store).string() + " from " +
                           callingAet_ + ": " + why + "; " + std::to_string(stored_) +
                           " object(s) of the association stored");
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
        const Uint16 status =
            fileObject(std::move(dataset), request.AffectedSOPClassUID,
                       request.AffectedSOPInstanceUID, info.acceptedTransferSyntax.c_str(),
                       {settings_.store, settings_.minFreeBytes, " from " + callingAet_,
                        marks_ ? &*marks_ : nullptr},
                       shared_);
        stored_ += status == 0 ? 1 : 0;
        failed_ += status == 0 ? 0 : 1;
        return sendSTOREResponse(info.presentationContextID, request, status);
    }

    const ScpSettings& settings_;
    StoreShared& shared_;
    std::string callingAet_;
    std::string callingHost_;
    std::uint64_t associationBytes_ = 0;
    std::uint64_t objectBytes_ = 0;
    bool overQuota_ = false;
    int stored_ = 0;
    int failed_ = 0;
    bool released_ = false;
    std::string ending_ = "the connection ended or the node stopped";
    std::optional<SeriesMarks> marks_;
};

} // namespace

void serveStoreAssociation(T_ASC_Association* assoc, const ScpSettings& settings,
                           StoreShared& shared) {
    StoreAssociation scp(settings, shared);
    // run() negotiates, serves the commands and drops and destroys the association; what went
    // wrong on the way is reported by the hooks above.
    (void)scp.run(assoc);
    scp.finishSeries();
}

} // namespace steerseg::net
