#pragma once

// The options `send` and `listen` share: the [dicom] section (system file, then --config FILE)
// as the defaults, and the command line's words over it.
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

// The outbox of [dicom] (its folder and retry delays), each attempt recorded in `audit`.
net::Outbox configuredOutbox(const config::DicomConfig& dicom, workflow::AuditLog& audit);

} // namespace steerseg::cli
