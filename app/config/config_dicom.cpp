// [dicom] and its [[dicom.peers]]: the DICOM node's own AE title and port, its incoming store
// and outbox, the peers it takes from and sends to, and its TLS files (docs/dicom-network.md).
#include "config/config_sections.hpp"
#include "config/key_names.hpp"
#include "model/ae_title.hpp"
#include "model/pacs_search.hpp"

#include <algorithm>
#include <utility>

namespace steerseg::config::detail {
namespace {

constexpr std::size_t kMaxPeers = 32; // a site's scanners and archives, not a directory
constexpr IntRange kPortRange{1, 65535};

std::string aeTitle(std::string_view text) {
    return model::aeTitleProblem(text);
}

// A host name or address as the resolver takes it: no blank, no control character.
std::string hostProblem(std::string_view text) {
    if (text.empty() || text.size() > 253) {
        return "must be a host name or address of 1 to 253 characters";
    }
    if (std::any_of(text.begin(), text.end(), [](char c) { return c <= ' ' || c > '~'; })) {
        return "must be a host name or address, without blanks";
    }
    return "";
}

std::string pathProblem(std::string_view text) {
    return text.empty() ? "must not be empty" : "";
}

// Reads one entry into `peer`; false when it cannot be used (the problem is reported).
bool readPeer(TableReader& t, DicomPeerConfig& peer) {
    const auto required = [&](std::string_view key) {
        if (!t.has(key)) {
            t.sink().add(t.source().source(), t.path(key), "is missing: every peer needs one");
            return false;
        }
        return true;
    };
    // Every missing key is reported, so no short-circuit.
    bool good = required("name");
    good = required("aet") && good;
    good = required("host") && good;
    if (auto v = t.text("name", [](std::string_view n) {
            return isControlName(n) ? "" : "must be 1 to 32 of a-z, 0-9 and _";
        })) {
        peer.name = *v;
    } else {
        good = false;
    }
    if (auto v = t.text("aet", aeTitle)) {
        peer.aet = *v;
    } else {
        good = false;
    }
    if (auto v = t.text("host", hostProblem)) {
        peer.host = *v;
    } else {
        good = false;
    }
    if (auto v = t.integer("port", kPortRange)) {
        peer.port = static_cast<int>(*v);
    } else if (t.has("port")) {
        good = false;
    }
    if (auto v = t.text("address", hostProblem)) {
        peer.address = *v;
    } else if (t.has("address")) {
        good = false;
    }
    if (auto v = t.boolean("receive")) {
        peer.receive = *v;
    }
    if (auto v = t.boolean("send")) {
        peer.send = *v;
    }
    if (auto v = t.boolean("tls")) {
        peer.tls = *v;
    }
    if (auto v = t.boolean("query")) {
        peer.query = *v;
    }
    if (auto v = t.text("retrieve", [](std::string_view word) {
            return word == "get" || word == "move" ? "" : "must be \"get\" or \"move\"";
        })) {
        peer.retrieve =
            *v == "move" ? DicomPeerConfig::Retrieve::Move : DicomPeerConfig::Retrieve::Get;
    } else if (t.has("retrieve")) {
        good = false;
    }
    if (good && !peer.receive && !peer.send && !peer.query) {
        t.sink().add(t.source().source(), t.path("receive"),
                     "a peer must be allowed to send to the console (receive = true), be a "
                     "target of exports (send = true), be queried (query = true), or more");
        good = false;
    }
    return good;
}

std::string knownList(const std::vector<std::string_view>& names) {
    std::string list;
    for (const std::string_view n : names) {
        list += (list.empty() ? "" : ", ") + std::string(n);
    }
    return list;
}

// A list of names from `known`, none twice; `out` only when every entry is good. An empty list
// is refused where `allowEmpty` is false.
void readNames(TableReader& t, std::string_view key, const std::vector<std::string_view>& known,
               bool allowEmpty, std::vector<std::string>& out) {
    const toml::array* list = t.array(key);
    if (list == nullptr) {
        return;
    }
    std::vector<std::string> read;
    bool good = true;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string path = t.path(key) + '[' + std::to_string(i) + ']';
        auto name = readText(
            *list->get(i), path,
            [&](std::string_view n) -> std::string {
                if (std::find(known.begin(), known.end(), n) == known.end()) {
                    return "unknown name \"" + std::string(n) + "\"; known: " + knownList(known);
                }
                if (std::find(read.begin(), read.end(), n) != read.end()) {
                    return "\"" + std::string(n) + "\" is listed twice";
                }
                return "";
            },
            t.sink());
        if (name) {
            read.push_back(*name);
        } else {
            good = false;
        }
    }
    if (good && read.empty() && !allowEmpty) {
        t.problem(key, "must name at least one of " + knownList(known));
        good = false;
    }
    if (good) {
        out = std::move(read);
    }
}

void readPeers(const toml::array& entries, std::vector<DicomPeerConfig>& peers, ProblemSink& sink) {
    std::vector<DicomPeerConfig> next;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const toml::node& node = *entries.get(i);
        const std::string prefix = "dicom.peers[" + std::to_string(i + 1) + "]";
        const toml::table* table = node.as_table();
        if (table == nullptr) {
            sink.add(node.source(), prefix,
                     "expected a table ([[dicom.peers]]), got something else");
            continue;
        }
        TableReader t(*table, prefix, sink);
        DicomPeerConfig peer;
        const bool good = readPeer(t, peer);
        t.reportUnknownKeys();
        if (!good) {
            continue;
        }
        if (std::any_of(next.begin(), next.end(),
                        [&](const DicomPeerConfig& p) { return p.name == peer.name; })) {
            t.problem("name", "\"" + peer.name + "\" is given twice");
            continue;
        }
        if (next.size() >= kMaxPeers) {
            sink.add(table->source(), prefix, "more than 32 peers");
            continue;
        }
        next.push_back(std::move(peer));
    }
    peers = std::move(next);
}

} // namespace

void readDicom(TableReader& t, DicomConfig& d) {
    if (auto v = t.boolean("enabled")) {
        d.enabled = *v;
    }
    if (auto v = t.text("aet", aeTitle)) {
        d.aet = *v;
    }
    if (auto v = t.integer("port", kPortRange)) {
        d.port = static_cast<int>(*v);
    }
    if (auto v = t.text("store", pathProblem)) {
        d.store = *v;
    }
    if (auto v = t.text("outbox", pathProblem)) {
        d.outbox = *v;
    }
    if (auto v = t.integer("association_quota_mb", {1, 65536})) {
        d.associationQuotaMb = static_cast<int>(*v);
    }
    if (auto v = t.integer("min_free_mb", {0, 1048576})) {
        d.minFreeMb = static_cast<int>(*v);
    }
    if (auto v = t.integer("keep_days", {1, 3650})) {
        d.keepDays = static_cast<int>(*v);
    }
    if (auto v = t.integer("max_associations", {1, 64})) {
        d.maxAssociations = static_cast<int>(*v);
    }
    if (auto v = t.integer("negotiation_seconds", {1, 60})) {
        d.negotiationSeconds = static_cast<int>(*v);
    }
    if (auto v = t.number("retry_first_seconds", {0.0, 3600.0, true})) {
        d.retryFirstSeconds = *v;
    }
    if (auto v = t.number("retry_longest_seconds", {0.0, 86400.0, true})) {
        d.retryLongestSeconds = *v;
    }
    // "" = none; whether the files are there is checkDicomTls's, on the whole configuration.
    for (const auto& [key, path] : {std::pair{"tls_certificate", &d.tlsCertificate},
                                    std::pair{"tls_private_key", &d.tlsPrivateKey},
                                    std::pair{"tls_ca_certificates", &d.tlsCaCertificates}}) {
        if (auto v = t.text(key)) {
            *path = *v;
        }
    }
    if (auto v = t.boolean("tls_receive")) {
        d.tlsReceive = *v;
    }
    if (t.has("tls")) {
        // Read so that it is not reported as merely unknown: the key a site would guess.
        t.boolean("tls");
        t.problem("tls", "TLS is set per peer (tls = true in [[dicom.peers]]) and for the port "
                         "(tls_receive), with tls_certificate, tls_private_key and "
                         "tls_ca_certificates");
    }
    // The kiosk's search form: a site without a query peer never shows it, whatever these say.
    readNames(t, "search_fields", model::searchFieldNames(), false, d.searchFields);
    readNames(t, "search_date_presets", model::datePresetNames(), true, d.searchDatePresets);
    if (auto v = t.integer("query_timeout_seconds", {1, 300})) {
        d.queryTimeoutSeconds = static_cast<int>(*v);
    }
    if (const toml::array* peers = t.array("peers")) {
        readPeers(*peers, d.peers, t.sink());
    }
}

} // namespace steerseg::config::detail
