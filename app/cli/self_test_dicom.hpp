#pragma once

// `steerseg --self-test`'s checks of the DICOM node ([dicom]): its port can be bound, its store
// and outbox written, its TLS certificate and key load and match and its CAs load (where it has
// them), and each configured peer answers C-ECHO, over TLS where it has tls (a warning, not a
// failure, when one does not: a PACS down for maintenance must not stop the console).
#include "cli/self_test_checks.hpp"
#include "config/kiosk_config.hpp"

#include <vector>

namespace steerseg::cli {

// One Ok line when the node is off; else the port, the two folders, TLS and a line per peer.
std::vector<CheckResult> checkDicomNode(const config::DicomConfig& dicom);

} // namespace steerseg::cli
