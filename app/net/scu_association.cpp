#include "net/scu_association.hpp"

#include "net/dcmtk_quiet.hpp"

#include <cstdio>

namespace steerseg::net {

std::string associationProblem(const DicomPeer& peer, const OFCondition& c) {
    std::string what = c.text();
    if (c == DUL_ASSOCIATIONREJECTED) {
        return "association rejected by " + describe(peer) + " (" + what + ")";
    }
    if (what.find("refused") != std::string::npos) {
        return "connection refused by " + describe(peer);
    }
    return "no association with " + describe(peer) + (peer.tls ? " over TLS: " : ": ") + what;
}

std::string exchangeProblem(const DicomPeer& peer, const std::string& what, const OFCondition& c,
                            int timeoutSeconds) {
    if (c == DIMSE_NODATAAVAILABLE) {
        return "no answer from " + describe(peer) + " within " + std::to_string(timeoutSeconds) +
               " s";
    }
    return what + " with " + describe(peer) + " failed: " + c.text();
}

PeerScu::PeerScu(const DicomPeer& peer, const ScuOptions& options)
    : peer_(peer), options_(options) {
    quietDcmtk();
    setAETitle(options_.callingAet.c_str());
    setPeerHostName(peer_.host.c_str());
    setPeerPort(static_cast<Uint16>(peer_.port));
    setPeerAETitle(peer_.aet.c_str());
    setConnectionTimeout(options_.timeoutSeconds);
    setACSETimeout(static_cast<Uint32>(options_.timeoutSeconds));
    setDIMSETimeout(static_cast<Uint32>(options_.timeoutSeconds));
    setDIMSEBlockingMode(DIMSE_NONBLOCKING);
    setVerbosePCMode(OFFalse);
    setProgressNotificationMode(OFFalse);
}

PeerScu::~PeerScu() {
    // ~DcmSCU would do the same, but only after tls_ is gone.
    if (isConnected()) {
        closeAssociation(DCMSCU_ABORT_ASSOCIATION);
    } else {
        freeNetwork();
    }
}

std::string PeerScu::associate() {
    OFCondition c = initNetwork();
    if (c.good() && peer_.tls) {
        try {
            tls_ = std::make_unique<TlsContext>(options_.tls, TlsRole::Requestor, peer_.host);
        } catch (const TlsError& e) {
            return "no TLS to " + describe(peer_) + ": " + e.what();
        }
        c = useSecureConnection(&tls_->layer());
    }
    if (c.good()) {
        c = negotiateAssociation();
    }
    if (c == DUL_READTIMEOUT) {
        return "no association with " + describe(peer_) + ": no answer within " +
               std::to_string(options_.timeoutSeconds) + " s";
    }
    return c.bad() ? associationProblem(peer_, c) : "";
}

void PeerScu::finish(bool release) {
    if (!isConnected()) {
        return;
    }
    if (release) {
        releaseAssociation();
    } else {
        abortAssociation();
    }
}

namespace {

// PS3.4 B.2.3, C.4.1.1.4, C.4.2.1.5 and C.4.3.1.4 (C-MOVE's 0xA801 is retrieve_scu's).
std::string statusMeaning(Uint16 status) {
    if ((status & 0xFF00) == 0xA700) {
        return "out of resources";
    }
    if ((status & 0xFF00) == 0xA900) {
        return "does not match the SOP class";
    }
    if ((status & 0xFF00) == 0xAA00) {
        return "frames not retrievable";
    }
    if ((status & 0xF000) == 0xC000) {
        return "unable to process";
    }
    if (status == 0x0122) {
        return "SOP class not supported";
    }
    if (status == 0x0124) {
        return "refused: not authorized";
    }
    return "failure";
}

} // namespace

std::string statusProblem(const DicomPeer& peer, Uint16 status) {
    char code[8];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(status));
    return describe(peer) + " answered " + code + " (" + statusMeaning(status) + ")";
}

} // namespace steerseg::net
