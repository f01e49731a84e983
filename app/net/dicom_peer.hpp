#pragma once

// Who is on the other end of a DICOM association: the peer's AE title and where it listens.
#include <string>

namespace steerseg::net {

struct DicomPeer {
    std::string aet;
    std::string host;
    int port = 104;
    bool tls = false; // the association runs over TLS (net/tls_context)
};

// "AE@host:port", for one-line messages.
std::string describe(const DicomPeer& peer);

} // namespace steerseg::net
