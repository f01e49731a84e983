#include "cli/self_test_dicom.hpp"

#include "kiosk/dicom_node_config.hpp"
#include "net/port_socket.hpp"
#include "net/store_scu.hpp"
#include "net/tls_context.hpp"

#include <unistd.h>

namespace steerseg::cli {
namespace {

// Binds the port on every address, as the SCP will, and lets it go again.
CheckResult checkPort(int port) {
    std::string problem;
    const int fd = net::bindPort(port, 0, problem);
    if (fd < 0) {
        return {"dicom port",
                CheckLevel::Fail,
                std::to_string(port) + " cannot be bound: " + problem,
                {}};
    }
    ::close(fd);
    return {"dicom port", CheckLevel::Ok, std::to_string(port) + " can be bound", {}};
}

// The files load as the node will load them: certificate and key, matching, and the CAs.
CheckResult checkTls(const net::TlsSettings& tls) {
    try {
        const net::TlsContext context(tls, net::TlsRole::Acceptor);
        return {"dicom tls", CheckLevel::Ok, context.summary() + "; the key matches", {}};
    } catch (const net::TlsError& e) {
        return {"dicom tls", CheckLevel::Fail, e.what(), {}};
    }
}

} // namespace

std::vector<CheckResult> checkDicomNode(const config::DicomConfig& dicom) {
    if (!dicom.enabled) {
        return {{"dicom node", CheckLevel::Ok, "off ([dicom] enabled = false)", {}}};
    }
    std::vector<CheckResult> results;
    results.push_back(checkPort(dicom.port));
    results.push_back(checkWritableFolder("dicom store", dicom.store));
    results.push_back(checkWritableFolder("dicom outbox", dicom.outbox));
    net::SendOptions options = kiosk::sendOptions(dicom);
    options.timeoutSeconds = 5;
    if (!dicom.tlsCertificate.empty() || !dicom.tlsPrivateKey.empty() ||
        !dicom.tlsCaCertificates.empty()) {
        results.push_back(checkTls(options.tls));
    }
    for (const auto& peer : dicom.peers) {
        const std::string problem = net::echo({peer.aet, peer.host, peer.port, peer.tls}, options);
        results.push_back({"dicom peer " + peer.name,
                           problem.empty() ? CheckLevel::Ok : CheckLevel::Warn,
                           problem.empty() ? peer.aet + " answers C-ECHO" : problem,
                           {}});
    }
    return results;
}

} // namespace steerseg::cli
