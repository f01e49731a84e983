#include "kiosk/dicom_node_config.hpp"

#include <chrono>

namespace steerseg::kiosk {

net::ScpSettings scpSettings(const config::DicomConfig& dicom) {
    net::ScpSettings s;
    s.aet = dicom.aet;
    s.port = dicom.port;
    s.store = dicom.store;
    s.associationQuotaBytes = static_cast<std::uint64_t>(dicom.associationQuotaMb) << 20;
    s.minFreeBytes = static_cast<std::uint64_t>(dicom.minFreeMb) << 20;
    s.keepDays = dicom.keepDays;
    s.maxAssociations = dicom.maxAssociations;
    s.negotiationSeconds = dicom.negotiationSeconds;
    for (const auto& peer : dicom.peers) {
        if (peer.receive) {
            s.allowed.push_back({peer.aet, peer.address});
        }
    }
    if (dicom.tlsReceive) {
        s.tls = tlsSettings(dicom);
    }
    return s;
}

net::TlsSettings tlsSettings(const config::DicomConfig& dicom) {
    return {dicom.tlsCertificate, dicom.tlsPrivateKey, dicom.tlsCaCertificates};
}

net::SendOptions sendOptions(const config::DicomConfig& dicom) {
    net::SendOptions options;
    options.callingAet = dicom.aet;
    options.tls = tlsSettings(dicom);
    return options;
}

std::optional<net::DicomPeer> sendPeer(const config::DicomConfig& dicom, const std::string& name) {
    for (const auto& p : dicom.peers) {
        if (p.name == name && p.send) {
            return net::DicomPeer{p.aet, p.host, p.port, p.tls};
        }
    }
    return std::nullopt;
}

std::optional<QueryPeer> queryPeer(const config::DicomConfig& dicom, const std::string& name) {
    for (const auto& p : dicom.peers) {
        if (p.name == name && p.query) {
            return QueryPeer{net::DicomPeer{p.aet, p.host, p.port, p.tls},
                             p.retrieve == config::DicomPeerConfig::Retrieve::Move
                                 ? net::RetrieveMethod::Move
                                 : net::RetrieveMethod::Get,
                             p.address};
        }
    }
    return std::nullopt;
}

std::vector<std::string> sendPeerNames(const config::DicomConfig& dicom) {
    std::vector<std::string> names;
    for (const auto& p : dicom.peers) {
        if (p.send) {
            names.push_back(p.name);
        }
    }
    return names;
}

net::OutboxBackoff outboxBackoff(const config::DicomConfig& dicom) {
    const auto ms = [](double seconds) {
        return std::chrono::duration_cast<std::chrono::milliseconds>(
            std::chrono::duration<double>(seconds));
    };
    return {ms(dicom.retryFirstSeconds), ms(dicom.retryLongestSeconds)};
}

} // namespace steerseg::kiosk
