#include "net/test_pki.hpp"

#include "net/net_harness.hpp"

#include <fstream>
#include <stdexcept>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

void openssl(const std::vector<std::string>& args, const fs::path& folder) {
    std::vector<std::string> argv{"openssl"};
    argv.insert(argv.end(), args.begin(), args.end());
    const Finished done = runProgram(argv, folder);
    if (done.status != 0) {
        throw std::runtime_error("openssl " + args.front() + " failed: " + done.output);
    }
}

void selfSignedCa(const fs::path& folder, const std::string& name) {
    openssl({"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-sha256", "-days", "2", "-subj",
             "/CN=steerseg test " + name, "-keyout", (folder / (name + ".key")).string(), "-out",
             (folder / (name + ".pem")).string()},
            folder);
}

void signed_(const fs::path& folder, const std::string& name, const std::string& ca,
             const std::string& extensions) {
    const fs::path key = folder / (name + ".key");
    const fs::path request = folder / (name + ".csr");
    openssl({"req", "-newkey", "rsa:2048", "-nodes", "-subj", "/CN=" + name, "-keyout",
             key.string(), "-out", request.string()},
            folder);
    openssl({"x509", "-req", "-sha256", "-days", "2", "-in", request.string(), "-CA",
             (folder / (ca + ".pem")).string(), "-CAkey", (folder / (ca + ".key")).string(),
             "-CAcreateserial", "-extfile", (folder / "extensions.cnf").string(), "-extensions",
             extensions, "-out", (folder / (name + ".pem")).string()},
            folder);
}

} // namespace

TestPki makeTestPki(const fs::path& folder) {
    fs::create_directories(folder);
    std::ofstream(folder / "extensions.cnf")
        << "[server]\nsubjectAltName = IP:127.0.0.1, DNS:localhost\n"
           "extendedKeyUsage = serverAuth, clientAuth\n"
           "[client]\nextendedKeyUsage = clientAuth, serverAuth\n";
    selfSignedCa(folder, "ca");
    selfSignedCa(folder, "other-ca");
    signed_(folder, "server", "ca", "server");
    signed_(folder, "client", "ca", "client");
    signed_(folder, "stranger", "other-ca", "client");
    const auto at = [&](const std::string& name) { return folder / name; };
    return {at("ca.pem"),     at("other-ca.pem"), at("server.pem"),   at("server.key"),
            at("client.pem"), at("client.key"),   at("stranger.pem"), at("stranger.key")};
}

} // namespace steerseg::test
