#pragma once

// Internal to net: the association pool's TLS side. The pool runs each connection's handshake
// itself, without blocking (AssociationPool::tlsRequest, defined in association_tls.cpp), and
// hands DCMTK a connection that gives back the association request the pool has already read.
#include <memory>
#include <vector>

class DcmTransportConnection;
struct ssl_st;

namespace steerseg::net {

// The connection DCMTK is handed for `fd` once `ssl`'s handshake is done and `request` (the
// A-ASSOCIATE-RQ's bytes) read through it; it owns `ssl` and, once DCMTK has it, the socket.
std::unique_ptr<DcmTransportConnection> readyTlsConnection(int fd, ssl_st* ssl,
                                                           std::vector<unsigned char> request);

} // namespace steerseg::net
