// --self-test's DICOM node checks: off by default in one line; when on, a port another process
// holds fails, a peer that does not answer is a warning naming why, and the TLS files load and
// match or fail naming the file.
#include "cli/self_test_dicom.hpp"
#include "net/net_harness.hpp"
#include "net/test_pki.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

using cli::CheckLevel;

// A listening socket on a kernel-chosen loopback port; its port, the socket closed at the end.
struct HeldPort {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    int port = 0;
    HeldPort() {
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_addr.s_addr = htonl(INADDR_ANY);
        ::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr);
        ::listen(fd, 1);
        socklen_t length = sizeof addr;
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &length);
        port = ntohs(addr.sin_port);
    }
    ~HeldPort() { ::close(fd); }
};

TEST(SelfTestDicom, OffIsOneOkLine) {
    const auto results = cli::checkDicomNode(config::DicomConfig{});
    ASSERT_EQ(results.size(), 1u);
    EXPECT_EQ(results[0].level, CheckLevel::Ok);
    EXPECT_NE(results[0].detail.find("off"), std::string::npos);
}

TEST(SelfTestDicom, AHeldPortFailsAndADeadPeerWarns) {
    const auto dir = tempDir("self-test-dicom");
    const HeldPort held;
    const HeldPort dead; // closed below: nothing listens there any more
    const int deadPort = dead.port;
    ::close(dead.fd);
    config::DicomConfig dicom;
    dicom.enabled = true;
    dicom.port = held.port;
    dicom.store = dir / "in";
    dicom.outbox = dir / "out";
    dicom.peers.push_back({"pacs", "PACS", "127.0.0.1", deadPort, "", false, true});
    const auto results = cli::checkDicomNode(dicom);
    ASSERT_EQ(results.size(), 4u);
    EXPECT_EQ(results[0].name, "dicom port");
    EXPECT_EQ(results[0].level, CheckLevel::Fail);
    EXPECT_NE(results[0].detail.find("cannot be bound"), std::string::npos) << results[0].detail;
    EXPECT_EQ(results[1].level, CheckLevel::Ok) << results[1].detail;
    EXPECT_EQ(results[2].level, CheckLevel::Ok) << results[2].detail;
    EXPECT_EQ(results[3].name, "dicom peer pacs");
    EXPECT_EQ(results[3].level, CheckLevel::Warn);
    EXPECT_NE(results[3].detail.find("connection refused"), std::string::npos) << results[3].detail;
    std::filesystem::remove_all(dir);
}

TEST(SelfTestDicom, TlsFilesLoadAndMatchOrFailNamingTheFile) {
    STEERSEG_REQUIRE_PROGRAM("/usr/bin/openssl", "openssl");
    const auto dir = tempDir("self-test-dicom-tls");
    const TestPki pki = makeTestPki(dir / "pki");
    config::DicomConfig dicom;
    dicom.enabled = true;
    dicom.port = HeldPort().port; // free again once the socket is closed
    dicom.store = dir / "in";
    dicom.outbox = dir / "out";
    const auto tlsLine = [&] {
        const auto results = cli::checkDicomNode(dicom);
        const auto it = std::find_if(results.begin(), results.end(), [](const cli::CheckResult& r) {
            return r.name == "dicom tls";
        });
        return it != results.end() ? *it : cli::CheckResult{"none", CheckLevel::Fail, "", {}};
    };
    EXPECT_EQ(tlsLine().name, "none"); // no TLS files, no line

    dicom.tlsCertificate = pki.serverCert;
    dicom.tlsPrivateKey = pki.serverKey;
    dicom.tlsCaCertificates = pki.ca;
    const cli::CheckResult good = tlsLine();
    EXPECT_EQ(good.level, CheckLevel::Ok) << good.detail;
    EXPECT_NE(good.detail.find("CN=server"), std::string::npos) << good.detail;
    EXPECT_NE(good.detail.find("1 trusted"), std::string::npos) << good.detail;

    dicom.tlsPrivateKey = pki.clientKey; // another certificate's key
    const cli::CheckResult mismatch = tlsLine();
    EXPECT_EQ(mismatch.level, CheckLevel::Fail);
    EXPECT_NE(mismatch.detail.find("does not belong"), std::string::npos) << mismatch.detail;

    dicom.tlsPrivateKey = pki.serverKey;
    dicom.tlsCaCertificates = pki.serverKey; // no certificate in it
    const cli::CheckResult noCa = tlsLine();
    EXPECT_EQ(noCa.level, CheckLevel::Fail);
    EXPECT_NE(noCa.detail.find(pki.serverKey.string()), std::string::npos) << noCa.detail;
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
