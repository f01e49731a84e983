#pragma once

// The options `send`, `listen`, `query` and `retrieve` share: the [dicom] section (system file,
// then --config FILE) as the defaults, and the command line's words over it.
#include "cli/args.hpp"
#include "config/kiosk_config.hpp"
#include "kiosk/dicom_node_config.hpp"
#include "net/dicom_peer.hpp"
#include "net/outbox.hpp"
#include "net/store_scp.hpp"

#include <optional>
#include <string>

namespace steerseg::cli {

// The system file and --config FILE (for [dicom] and [audit]); a problem in either is a
// UsageError naming its place, so the node never runs on half a configuration.
config::KioskConfig nodeConfig(const Args& args);

// --to PEER (a [[dicom.peers]] name with send = true) or --host H --port N --called-aet AE
// [--tls].
net::DicomPeer sendTarget(const Args& args, const config::DicomConfig& dicom);

// --aet, else [dicom] aet.
std::string ownAeTitle(const Args& args, const config::DicomConfig& dicom);

// --aet, --port, --store, --allow AE[@ADDRESS] ..., --quota-mb, --tls over [dicom]; with no
// --allow, the peers with receive = true.
net::ScpSettings listenSettings(const Args& args, const config::DicomConfig& dicom);

// The [[dicom.peers]] entry named `name` with send = true, as an address; nullopt if none.
using kiosk::sendPeer;
// The same, or a UsageError for --to naming it.
net::DicomPeer requireSendPeer(const config::DicomConfig& dicom, const std::string& name);

// --to PEER for query and retrieve: the [[dicom.peers]] entry with query = true, or a
// UsageError saying whether no peer has the name or the peer may not be queried.
kiosk::QueryPeer requireQueryPeer(const Args& args, const config::DicomConfig& dicom);

// --timeout S (1..600, default 30): how long query and retrieve wait for the connection, the
// association and each response.
int scuTimeoutSeconds(const Args& args);

// The outbox of [dicom] (its folder and retry delays), each attempt recorded in `audit`.
net::Outbox configuredOutbox(const config::DicomConfig& dicom, workflow::AuditLog& audit);

} // namespace steerseg::cli
