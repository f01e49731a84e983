#include "net/dicom_peer.hpp"

namespace steerseg::net {

std::string describe(const DicomPeer& peer) {
    return peer.aet + "@" + peer.host + ":" + std::to_string(peer.port);
}

} // namespace steerseg::net
