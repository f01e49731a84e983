#pragma once

// Certificates for the TLS tests, made by the `openssl` command line in a test's own folder: a
// CA, a server and a client certificate it signed (the server's naming 127.0.0.1 and
// localhost), and a "stranger" signed by another CA that nobody trusts. RSA, since DICOM's BCP
// 195 profiles negotiate RSA cipher suites.
#include <filesystem>

namespace steerseg::test {

struct TestPki {
    std::filesystem::path ca;         // ca.pem: the trusted CA's certificate
    std::filesystem::path otherCa;    // other-ca.pem: a CA nobody here trusts
    std::filesystem::path serverCert; // signed by ca, for 127.0.0.1 and localhost
    std::filesystem::path serverKey;
    std::filesystem::path clientCert; // signed by ca
    std::filesystem::path clientKey;
    std::filesystem::path strangerCert; // signed by the other CA
    std::filesystem::path strangerKey;
};

// Makes them under `folder`; throws std::runtime_error with openssl's output when it fails.
TestPki makeTestPki(const std::filesystem::path& folder);

} // namespace steerseg::test
