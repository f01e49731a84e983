#pragma once

// How the node calls a peer, whatever it then asks (C-STORE, C-ECHO, C-FIND, C-GET, C-MOVE):
// its own AE title, how long it waits, and its TLS credentials for a peer with `tls`.
#include "net/tls_context.hpp"

#include <string>

namespace steerseg::net {

struct ScuOptions {
    std::string callingAet = "STEERSEG";
    int timeoutSeconds = 30; // TCP connect, ACSE and each DIMSE message
    TlsSettings tls;         // the node's credentials, for a peer with `tls`
};

} // namespace steerseg::net
