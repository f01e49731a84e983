// The association pool's TLS side (association_tls.hpp): each handshake run without blocking,
// the request read through it, and the connection DCMTK is handed afterwards.
#include "net/association_tls.hpp"

#include "net/association_pdu.hpp"
#include "net/association_pool.hpp"

#include <algorithm>
#include <cstring>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmtls/tlstrans.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <string>
#include <utility>

namespace steerseg::net {

namespace {

// OpenSSL's reason for the failure just seen, in one line.
std::string tlsReason(int sslError) {
    const unsigned long e = ERR_get_error();
    ERR_clear_error();
    if (e != 0) {
        const char* reason = ERR_reason_error_string(e);
        return reason != nullptr ? reason : "error " + std::to_string(e);
    }
    return sslError == SSL_ERROR_SYSCALL || sslError == SSL_ERROR_ZERO_RETURN
               ? "the connection ended during the handshake"
               : "handshake failed (OpenSSL error " + std::to_string(sslError) + ")";
}

// The connection DCMTK is handed: the pool has run its handshake and read the association
// request through it (DCMTK must still read that request, so it is given back first).
class ReadyTlsConnection : public DcmTLSConnection {
  public:
    ReadyTlsConnection(int fd, SSL* ssl, std::vector<unsigned char> request)
        : DcmTLSConnection(fd, ssl), request_(std::move(request)) {}

    OFCondition serverSideHandshake() override { return EC_Normal; }

    ssize_t read(void* buf, size_t nbyte) override {
        if (given_ < request_.size()) {
            const std::size_t n = std::min(nbyte, request_.size() - given_);
            std::memcpy(buf, request_.data() + given_, n);
            given_ += n;
            return static_cast<ssize_t>(n);
        }
        return DcmTLSConnection::read(buf, nbyte);
    }

    OFBool networkDataAvailable(int timeout) override {
        return given_ < request_.size() ? OFTrue : DcmTLSConnection::networkDataAvailable(timeout);
    }

  private:
    std::vector<unsigned char> request_;
    std::size_t given_ = 0;
};

} // namespace

std::unique_ptr<DcmTransportConnection> readyTlsConnection(int fd, ssl_st* ssl,
                                                           std::vector<unsigned char> request) {
    return std::make_unique<ReadyTlsConnection>(fd, ssl, std::move(request));
}

// The handshake as far as the peer's bytes take it (the socket does not block), then the
// association request read through it. A handshake that stops half way is one more pending
// connection that waits for its deadline, beside the others.
AssociationPool::Request AssociationPool::tlsRequest(Pending& p, std::string& why) const {
    if (p.ssl == nullptr) {
        p.ssl = SSL_new(tls_);
        if (p.ssl == nullptr || SSL_set_fd(p.ssl, p.fd) != 1) {
            why = tlsReason(SSL_ERROR_SSL);
            return Request::Refused;
        }
    }
    const auto wants = [&p](int error) {
        if (error == SSL_ERROR_WANT_READ || error == SSL_ERROR_WANT_WRITE) {
            p.events = error == SSL_ERROR_WANT_READ ? POLLIN : POLLOUT;
            return true;
        }
        return false;
    };
    if (!p.handshaken) {
        ERR_clear_error();
        const int r = SSL_accept(p.ssl);
        if (r != 1) {
            const int error = SSL_get_error(p.ssl, r);
            if (wants(error)) {
                return Request::Waiting;
            }
            why = tlsReason(error);
            return Request::Refused;
        }
        p.handshaken = true;
    }
    // Exactly the request's bytes: what follows it is DCMTK's to read.
    std::size_t needed = kPduHead;
    for (;;) {
        if (p.request.size() >= kPduHead) {
            if (p.request[0] != kAssociateRequest ||
                pduLength(p.request.data()) > kMaxRequestBytes) {
                return Request::NotOne;
            }
            needed = kPduHead + pduLength(p.request.data());
        }
        if (p.request.size() >= needed) {
            return Request::Whole;
        }
        const std::size_t have = p.request.size();
        p.request.resize(needed);
        ERR_clear_error();
        const int n = SSL_read(p.ssl, p.request.data() + have, static_cast<int>(needed - have));
        p.request.resize(have + static_cast<std::size_t>(std::max(n, 0)));
        if (n <= 0) {
            return wants(SSL_get_error(p.ssl, n)) ? Request::Waiting : Request::Gone;
        }
    }
}

} // namespace steerseg::net
