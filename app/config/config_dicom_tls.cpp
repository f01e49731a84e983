// [dicom]'s TLS keys against each other and against the files they name, on the configuration a
// file would produce: a node that was asked for TLS must not come up speaking in clear, nor fail
// at its first association over a key file that was never there. The files' contents are only
// looked at for their PEM markers here; loading them (and whether key and certificate match) is
// the self-test's and the node's (net/tls_context).
#include "config/config_sections.hpp"

#include <fstream>
#include <iterator>

namespace steerseg::config::detail {
namespace {

namespace fs = std::filesystem;

constexpr std::streamsize kMaxPemBytes = 1 << 20; // a certificate chain, not a data file

// The node of `key` in this file's [dicom] (or its peer `peer`), else the nearest table that
// the file has, so that a problem points into the file that caused it.
const toml::node& place(const toml::table& root, std::string_view key, int peer = -1) {
    const toml::table* dicom = root["dicom"].as_table();
    if (dicom == nullptr) {
        return root;
    }
    const toml::table* table = dicom;
    if (peer >= 0) {
        const toml::array* peers = (*dicom)["peers"].as_array();
        const toml::node* entry =
            peers != nullptr ? peers->get(static_cast<std::size_t>(peer)) : nullptr;
        table = entry != nullptr ? entry->as_table() : nullptr;
        if (table == nullptr) {
            return *dicom;
        }
    }
    const toml::node* node = table->get(key);
    return node != nullptr ? *node : *table;
}

std::string readHead(const fs::path& path, std::string& problem) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (status.type() == fs::file_type::not_found) {
        problem = "\"" + path.string() + "\": no such file";
        return {};
    }
    if (status.type() != fs::file_type::regular) {
        problem = "\"" + path.string() + "\" is not a regular file";
        return {};
    }
    std::ifstream in(path, std::ios::binary);
    std::string text(static_cast<std::size_t>(kMaxPemBytes), '\0');
    in.read(text.data(), kMaxPemBytes);
    if (!in && !in.eof()) {
        problem = "\"" + path.string() + "\" cannot be read";
        return {};
    }
    text.resize(static_cast<std::size_t>(in.gcount()));
    return text;
}

std::string certificateProblem(const fs::path& path) {
    std::string problem;
    const std::string text = readHead(path, problem);
    if (problem.empty() && text.find("-----BEGIN CERTIFICATE-----") == std::string::npos) {
        problem =
            "\"" + path.string() + "\" holds no PEM certificate (-----BEGIN CERTIFICATE-----)";
    }
    return problem;
}

std::string privateKeyProblem(const fs::path& path) {
    std::string problem;
    const std::string text = readHead(path, problem);
    if (!problem.empty()) {
        return problem;
    }
    if (text.find("ENCRYPTED") != std::string::npos) {
        return "\"" + path.string() +
               "\" is encrypted: the node has nobody to ask for a password; give it the key "
               "unencrypted, readable by its user only";
    }
    if (text.find("PRIVATE KEY-----") == std::string::npos) {
        return "\"" + path.string() + "\" holds no PEM private key (-----BEGIN PRIVATE KEY-----)";
    }
    return "";
}

std::string trustedProblem(const fs::path& path) {
    std::error_code ec;
    return fs::is_directory(path, ec) ? "" : certificateProblem(path);
}

} // namespace

void checkDicomTls(const DicomConfig& d, const toml::table& root, ProblemSink& sink) {
    const auto add = [&](const toml::node& at, std::string key, std::string message) {
        sink.add(at.source(), std::move(key), std::move(message));
    };
    const struct {
        const char* key;
        const fs::path& path;
        std::string (*problem)(const fs::path&);
    } files[] = {{"tls_certificate", d.tlsCertificate, certificateProblem},
                 {"tls_private_key", d.tlsPrivateKey, privateKeyProblem},
                 {"tls_ca_certificates", d.tlsCaCertificates, trustedProblem}};
    bool complete = true;
    for (const auto& f : files) {
        if (f.path.empty()) {
            complete = false;
        } else if (std::string problem = f.problem(f.path); !problem.empty()) {
            add(place(root, f.key), std::string("dicom.") + f.key, std::move(problem));
        }
    }
    const std::string needs =
        "TLS needs the node's tls_certificate, tls_private_key and tls_ca_certificates in [dicom]";
    if (d.tlsReceive && !complete) {
        add(place(root, "tls_receive"), "dicom.tls_receive", needs);
    }
    for (std::size_t i = 0; i < d.peers.size(); ++i) {
        const DicomPeerConfig& p = d.peers[i];
        const std::string key = "dicom.peers[" + std::to_string(i + 1) + "].tls";
        const toml::node& at = place(root, "tls", static_cast<int>(i));
        // A C-MOVE's images come on an association the peer opens to the node's port.
        const bool callsIn =
            p.receive || (p.query && p.retrieve == DicomPeerConfig::Retrieve::Move);
        const std::string calling = p.receive ? "receive = true" : "retrieve = \"move\"";
        if (p.tls && !complete) {
            add(at, key, needs);
        } else if (callsIn && p.tls && !d.tlsReceive) {
            add(at, key,
                calling + " over TLS, but the node's port speaks plain DICOM: set "
                          "tls_receive = true in [dicom]");
        } else if (callsIn && !p.tls && d.tlsReceive) {
            add(at, key,
                calling + " without TLS, but the node's port speaks TLS only "
                          "(tls_receive = true): this peer could not call; set tls = true");
        }
    }
}

} // namespace steerseg::config::detail
