#include "cli/self_test_dicom.hpp"

#include "net/store_scu.hpp"

#include <cerrno>
#include <cstring>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace steerseg::cli {
namespace {

// Binds the port on every address, as the SCP will, and lets it go again.
CheckResult checkPort(int port) {
    CheckResult r{"dicom port", CheckLevel::Ok, std::to_string(port) + " can be bound", {}};
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        return {
            "dicom port", CheckLevel::Fail, std::string("no socket: ") + std::strerror(errno), {}};
    }
    const int on = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_ANY);
    if (::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
        r.level = CheckLevel::Fail;
        r.detail = std::to_string(port) + " cannot be bound: " + std::strerror(errno);
    }
    ::close(fd);
    return r;
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
    net::SendOptions options;
    options.callingAet = dicom.aet;
    options.timeoutSeconds = 5;
    for (const auto& peer : dicom.peers) {
        const std::string problem = net::echo({peer.aet, peer.host, peer.port}, options);
        results.push_back({"dicom peer " + peer.name,
                           problem.empty() ? CheckLevel::Ok : CheckLevel::Warn,
                           problem.empty() ? peer.aet + " answers C-ECHO" : problem,
                           {}});
    }
    return results;
}

} // namespace steerseg::cli
