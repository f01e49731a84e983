#pragma once

// Internal to net: the requesting side's association, one for every SCU of the node (store_scu,
// query_scu, retrieve_scu). DCMTK's DcmSCU set up for one peer with the node's calling AE title
// and timeouts, over TLS where the peer has it, and every way of not getting an association as
// one line. It names DCMTK's types, so only net's sources include it.
#include "net/dicom_peer.hpp"
#include "net/scu_options.hpp"
#include "net/tls_context.hpp"

#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmnet/scu.h>
#include <memory>
#include <string>

namespace steerseg::net {

class PeerScu : public DcmSCU {
  public:
    // Calling AE title, the peer's address and AE title, the three timeouts, non-blocking DIMSE
    // (so that every wait has its deadline), DCMTK's logging of contexts and progress off.
    PeerScu(const DicomPeer& peer, const ScuOptions& options);
    // Aborts an association still open before the TLS layer it runs on goes.
    ~PeerScu() override;
    PeerScu(const PeerScu&) = delete;
    PeerScu& operator=(const PeerScu&) = delete;

    // The network, TLS where the peer has it, the negotiation of the presentation contexts
    // added before: "" or why not in one line (connection refused, association rejected, no
    // TLS, the peer silent past the timeout).
    std::string associate();
    // Release when the peer is still talking, else abort: a peer that has gone silent would
    // hold a release for the ACSE timeout.
    void finish(bool release);

    [[nodiscard]] const DicomPeer& peer() const { return peer_; }
    [[nodiscard]] const ScuOptions& options() const { return options_; }

  private:
    DicomPeer peer_;
    ScuOptions options_;
    std::unique_ptr<TlsContext> tls_; // the transport layer DcmSCU borrows, not owns
};

// "association rejected by AE@host:port (...)", "connection refused by ...", "no association
// with ...: why".
std::string associationProblem(const DicomPeer& peer, const OFCondition& c);

// "AE@host:port answered 0xA700 (out of resources)": a DIMSE failure status in one line, in the
// words of PS3.4's status classes, which C-STORE, C-FIND, C-GET and C-MOVE share.
std::string statusProblem(const DicomPeer& peer, Uint16 status);

// A DIMSE exchange (`what`: "C-FIND") that failed after the association: "no answer from
// AE@host:port within N s" for a peer gone silent, else "C-FIND with AE@host:port failed: why".
std::string exchangeProblem(const DicomPeer& peer, const std::string& what, const OFCondition& c,
                            int timeoutSeconds);

} // namespace steerseg::net
