#pragma once

// The [dicom] section as the network node's pieces take it: the Storage SCP's settings, the
// send peers' addresses and the outbox's retry delays. The kiosk's node and the command line's
// `listen`, `send` and `export --send` read the config through these, so they cannot differ.
#include "config/kiosk_config.hpp"
#include "net/dicom_peer.hpp"
#include "net/outbox.hpp"
#include "net/retrieve_scu.hpp"
#include "net/store_scp.hpp"
#include "net/store_scu.hpp"
#include "net/tls_context.hpp"

#include <optional>
#include <string>
#include <vector>

namespace steerseg::kiosk {

// Own AE title, port, store, quotas, retention, and the peers with receive = true as the
// callers allowed (each pinned to its `address` where given); TLS only with tls_receive.
net::ScpSettings scpSettings(const config::DicomConfig& dicom);

// The [[dicom.peers]] entry named `name` with send = true, as an address; nullopt if none.
std::optional<net::DicomPeer> sendPeer(const config::DicomConfig& dicom, const std::string& name);

// A [[dicom.peers]] entry with query = true: where it is, how it retrieves, and the address
// its C-MOVE's images come from ("" = any).
struct QueryPeer {
    net::DicomPeer peer;
    net::RetrieveMethod retrieve = net::RetrieveMethod::Get;
    std::string address;
};
// The peer named `name` with query = true; nullopt if none.
std::optional<QueryPeer> queryPeer(const config::DicomConfig& dicom, const std::string& name);

// The names of the peers with send = true, in the config's order: where exports go.
std::vector<std::string> sendPeerNames(const config::DicomConfig& dicom);

// The node's certificate, private key and trusted CAs.
net::TlsSettings tlsSettings(const config::DicomConfig& dicom);

// Own AE title as the calling one, and the TLS credentials for the peers with tls = true.
net::SendOptions sendOptions(const config::DicomConfig& dicom);

// retry_first_seconds and retry_longest_seconds.
net::OutboxBackoff outboxBackoff(const config::DicomConfig& dicom);

} // namespace steerseg::kiosk
