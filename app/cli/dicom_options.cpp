#include "cli/dicom_options.hpp"

#include "config/config_loader.hpp"
#include "kiosk/dicom_node_config.hpp"
#include "model/action.hpp"
#include "model/ae_title.hpp"

#include <algorithm>

namespace steerseg::cli {
namespace {

std::string checkedAeTitle(const std::string& aet, const std::string& option) {
    if (const std::string problem = model::aeTitleProblem(aet); !problem.empty()) {
        throw UsageError(option + ": '" + aet + "': " + problem);
    }
    return aet;
}

int checkedPort(const Args& args, const std::string& name) {
    const long long port = *args.integer(name);
    if (port < 1 || port > 65535) {
        throw UsageError("--" + name + ": a port is 1..65535, got " + std::to_string(port));
    }
    return static_cast<int>(port);
}

// --tls: over the config's certificate, key and CAs, which it cannot do without.
net::TlsSettings requiredTls(const config::DicomConfig& dicom) {
    const net::TlsSettings tls = kiosk::tlsSettings(dicom);
    if (!tls.complete()) {
        throw UsageError("--tls needs [dicom] tls_certificate, tls_private_key and "
                         "tls_ca_certificates in the config");
    }
    return tls;
}

} // namespace

net::DicomPeer requireSendPeer(const config::DicomConfig& dicom, const std::string& name) {
    if (auto peer = sendPeer(dicom, name)) {
        return *peer;
    }
    throw UsageError("--to: no [[dicom.peers]] named '" + name + "' with send = true");
}

config::KioskConfig nodeConfig(const Args& args) {
    std::optional<std::filesystem::path> file;
    if (const auto c = args.value("config")) {
        file = *c;
    }
    const config::BindingCheck bindable = model::isBindable;
    const config::LoadedConfig loaded =
        config::loadConfig(config::kioskConfigSources(file), bindable);
    if (!loaded.problems.empty()) {
        throw UsageError(config::describe(loaded.problems.front()) +
                         (loaded.problems.size() > 1
                              ? " (and " + std::to_string(loaded.problems.size() - 1) + " more)"
                              : ""));
    }
    return loaded.config;
}

net::DicomPeer sendTarget(const Args& args, const config::DicomConfig& dicom) {
    const bool direct = args.value("host") || args.value("port") || args.value("called-aet");
    if (const auto name = args.value("to")) {
        if (direct) {
            throw UsageError("give --to PEER or --host, --port and --called-aet, not both");
        }
        if (args.flag("tls")) {
            throw UsageError("--tls goes with --host: a peer's tls is in its [[dicom.peers]]");
        }
        return requireSendPeer(dicom, *name);
    }
    if (!direct) {
        throw UsageError("give --to PEER, or --host, --port and --called-aet");
    }
    net::DicomPeer peer;
    peer.host = args.required("host");
    peer.port = checkedPort(args, "port");
    peer.aet = checkedAeTitle(args.required("called-aet"), "--called-aet");
    if (args.flag("tls")) {
        requiredTls(dicom);
        peer.tls = true;
    }
    return peer;
}

std::string ownAeTitle(const Args& args, const config::DicomConfig& dicom) {
    return checkedAeTitle(args.value("aet").value_or(dicom.aet), "--aet");
}

net::ScpSettings listenSettings(const Args& args, const config::DicomConfig& dicom) {
    net::ScpSettings s = kiosk::scpSettings(dicom);
    s.aet = ownAeTitle(args, dicom);
    s.port = args.value("port") ? checkedPort(args, "port") : dicom.port;
    s.store = args.value("store").value_or(dicom.store.string());
    if (const auto quota = args.integer("quota-mb")) {
        if (*quota < 1 || *quota > 65536) {
            throw UsageError("--quota-mb: 1..65536, got " + std::to_string(*quota));
        }
        s.associationQuotaBytes = static_cast<std::uint64_t>(*quota) << 20;
    }
    const std::vector<std::string> allow = args.values("allow");
    if (!allow.empty()) {
        s.allowed.clear(); // --allow replaces the config's peers
    }
    for (const std::string& word : allow) {
        const auto at = word.find('@');
        net::AllowedCaller caller{checkedAeTitle(word.substr(0, at), "--allow"),
                                  at == std::string::npos ? "" : word.substr(at + 1)};
        s.allowed.push_back(std::move(caller));
    }
    if (s.allowed.empty()) {
        throw UsageError("nobody may send: give --allow AE or [[dicom.peers]] with receive = true");
    }
    if (args.flag("tls")) {
        s.tls = requiredTls(dicom);
    }
    return s;
}

kiosk::QueryPeer requireQueryPeer(const Args& args, const config::DicomConfig& dicom) {
    const auto name = args.value("to");
    if (!name) {
        throw UsageError("give --to PEER, a [[dicom.peers]] name with query = true");
    }
    if (auto peer = kiosk::queryPeer(dicom, *name)) {
        return *peer;
    }
    const bool known = std::any_of(dicom.peers.begin(), dicom.peers.end(),
                                   [&](const auto& p) { return p.name == *name; });
    throw UsageError(known ? "--to: the peer '" + *name +
                                 "' may not be queried: give it query = true in [[dicom.peers]]"
                           : "--to: no [[dicom.peers]] named '" + *name + "'");
}

int scuTimeoutSeconds(const Args& args) {
    const long long seconds = args.integer("timeout").value_or(30);
    if (seconds < 1 || seconds > 600) {
        throw UsageError("--timeout: 1..600 seconds, got " + std::to_string(seconds));
    }
    return static_cast<int>(seconds);
}

net::Outbox configuredOutbox(const config::DicomConfig& dicom, workflow::AuditLog& audit) {
    return net::Outbox(dicom.outbox, kiosk::outboxBackoff(dicom), &audit);
}

} // namespace steerseg::cli
