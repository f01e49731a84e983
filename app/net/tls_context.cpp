// A thin wrapper of DCMTK's DcmTLSTransportLayer: every failure becomes one line naming the
// file, and the two things DCMTK leaves open are closed here: an encrypted key never prompts on
// a terminal (a service would hang), and a requestor checks the peer's name, not only its chain.
#include "net/tls_context.hpp"

#include <arpa/inet.h>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmtls/tlslayer.h>
#include <mutex>
#include <openssl/ssl.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>
#include <system_error>

namespace steerseg::net {
namespace {

namespace fs = std::filesystem;

void requireFile(const fs::path& path, const std::string& what) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        throw TlsError(what + " " + path.string() + ": no such file");
    }
}

void check(const OFCondition& c, const std::string& what) {
    if (c.bad()) {
        throw TlsError(what + ": " + c.text());
    }
}

// PEM certificates in a folder, whatever their names: OpenSSL's own folder lookup would want
// them renamed to their subject hashes (c_rehash), which a site should not have to know.
void addTrustedFolder(DcmTLSTransportLayer& layer, const fs::path& folder) {
    int added = 0;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
        const std::string ext = entry.path().extension().string();
        if (!entry.is_regular_file(ec) || (ext != ".pem" && ext != ".crt" && ext != ".cer")) {
            continue;
        }
        check(layer.addTrustedCertificateFile(entry.path().c_str(), DCF_Filetype_PEM),
              "cannot load the trusted certificate " + entry.path().string());
        ++added;
    }
    if (ec) {
        throw TlsError("cannot list the trusted certificates' folder " + folder.string() + ": " +
                       ec.message());
    }
    if (added == 0) {
        throw TlsError("the trusted certificates' folder " + folder.string() +
                       " holds no *.pem, *.crt or *.cer file");
    }
}

std::string subjectOf(const fs::path& certificate) {
    X509* cert = DcmTLSTransportLayer::loadCertificateFile(certificate.c_str(), DCF_Filetype_PEM);
    if (cert == nullptr) {
        return "?";
    }
    char name[256] = {};
    X509_NAME_oneline(X509_get_subject_name(cert), name, sizeof name);
    X509_free(cert);
    return name;
}

// The peer's certificate must name the host we dialled: an IP address against its IP entries,
// a name against its DNS names (OpenSSL's check, run within the chain's verification).
void requirePeerName(SSL_CTX* ctx, const std::string& host) {
    X509_VERIFY_PARAM* param = SSL_CTX_get0_param(ctx);
    unsigned char address[16];
    const bool numeric = inet_pton(AF_INET, host.c_str(), address) == 1 ||
                         inet_pton(AF_INET6, host.c_str(), address) == 1;
    const int ok = numeric ? X509_VERIFY_PARAM_set1_ip_asc(param, host.c_str())
                           : X509_VERIFY_PARAM_set1_host(param, host.c_str(), host.size());
    if (ok != 1) {
        throw TlsError("cannot check the peer's certificate against the host " + host);
    }
}

extern "C" int refusePassword(char* /*buf*/, int /*size*/, int /*rwflag*/, void* /*user*/) {
    return 0; // no password: an encrypted key fails to load instead of prompting
}

} // namespace

TlsContext::TlsContext(const TlsSettings& settings, TlsRole role, const std::string& peerHost) {
    if (!settings.complete()) {
        throw TlsError("TLS needs the node's certificate, private key and trusted CA "
                       "certificates ([dicom] tls_certificate, tls_private_key, "
                       "tls_ca_certificates)");
    }
    static std::once_flag openssl;
    std::call_once(openssl, [] { DcmTLSTransportLayer::initializeOpenSSL(); });
    layer_ = std::make_unique<DcmTLSTransportLayer>(
        role == TlsRole::Acceptor ? NET_ACCEPTOR : NET_REQUESTOR, nullptr, OFFalse);
    if (!*layer_) {
        throw TlsError("cannot set up TLS (OpenSSL " +
                       std::string(DcmTLSTransportLayer::getOpenSSLVersionName()) + ")");
    }
    SSL_CTX* ctx = layer_->getNativeHandle();
    SSL_CTX_set_default_passwd_cb(ctx, refusePassword);
    check(layer_->setTLSProfile(TSP_Profile_BCP195_ND), "TLS profile BCP 195");
    check(layer_->activateCipherSuites(), "TLS cipher suites");

    requireFile(settings.certificate, "the certificate");
    requireFile(settings.privateKey, "the private key");
    check(layer_->setPrivateKeyFile(settings.privateKey.c_str(), DCF_Filetype_PEM),
          "cannot load the private key " + settings.privateKey.string() +
              " (an unencrypted PEM key)");
    check(layer_->setCertificateFile(settings.certificate.c_str(), DCF_Filetype_PEM),
          "cannot load the certificate " + settings.certificate.string() + " (PEM)");
    if (!layer_->checkPrivateKeyMatchesCertificate()) {
        throw TlsError("the private key " + settings.privateKey.string() +
                       " does not belong to the certificate " + settings.certificate.string());
    }

    std::error_code ec;
    if (fs::is_directory(settings.trusted, ec)) {
        addTrustedFolder(*layer_, settings.trusted);
    } else {
        requireFile(settings.trusted, "the trusted CA certificates");
        check(layer_->addTrustedCertificateFile(settings.trusted.c_str(), DCF_Filetype_PEM),
              "cannot load the trusted CA certificates " + settings.trusted.string() + " (PEM)");
    }
    const int trusted = sk_X509_OBJECT_num(X509_STORE_get0_objects(SSL_CTX_get_cert_store(ctx)));
    layer_->setCertificateVerification(DCV_requireCertificate);
    if (role == TlsRole::Requestor && !peerHost.empty()) {
        requirePeerName(ctx, peerHost);
    }
    summary_ = subjectOf(settings.certificate) + ", " + std::to_string(trusted) +
               " trusted CA certificate(s)";
}

TlsContext::~TlsContext() = default;

DcmTransportLayer& TlsContext::layer() {
    return *layer_;
}

ssl_ctx_st* TlsContext::context() {
    return layer_->getNativeHandle();
}

} // namespace steerseg::net
