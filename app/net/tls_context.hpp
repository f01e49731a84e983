#pragma once

// DICOM over TLS (PS3.15 B.9, DCMTK's dcmtls over OpenSSL): the node's own certificate and
// private key, the certificate authorities it trusts, and the one transport layer per role that
// DCMTK's network takes. Both sides must show a certificate a trusted CA signed: an acceptor
// refuses a caller without one, a requestor a peer without one.
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

class DcmTLSTransportLayer;
class DcmTransportLayer;
struct ssl_ctx_st;

namespace steerseg::net {

struct TlsSettings {
    std::filesystem::path certificate; // PEM: the node's own certificate (chain)
    std::filesystem::path privateKey;  // PEM, unencrypted: a service has nobody to ask
    std::filesystem::path trusted;     // PEM file of CA certificates, or a folder of such files
    [[nodiscard]] bool complete() const {
        return !certificate.empty() && !privateKey.empty() && !trusted.empty();
    }
};

class TlsError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

enum class TlsRole { Acceptor, Requestor };

class TlsContext {
  public:
    // Loads the certificate and key (they must match) and the trusted CAs; TLS 1.2 or newer
    // only (DICOM's non-downgrading BCP 195 profile). A requestor given `peerHost` also insists
    // that the peer's certificate names that host or IP address, which DCMTK does not check by
    // itself. Throws TlsError with a one-line reason naming the file.
    TlsContext(const TlsSettings& settings, TlsRole role, const std::string& peerHost = {});
    ~TlsContext();
    TlsContext(const TlsContext&) = delete;
    TlsContext& operator=(const TlsContext&) = delete;

    // For ASC_setTransportLayer / DcmSCU; owned by this context, which must outlive its use.
    [[nodiscard]] DcmTransportLayer& layer();
    // OpenSSL's context under it (the same certificates, CAs, profile and verification), for an
    // acceptor that runs its handshakes itself (AssociationPool).
    [[nodiscard]] ssl_ctx_st* context();
    // The certificate's subject and how many CA certificates are trusted, for the self-test.
    [[nodiscard]] const std::string& summary() const { return summary_; }

  private:
    std::unique_ptr<DcmTLSTransportLayer> layer_;
    std::string summary_;
};

} // namespace steerseg::net
