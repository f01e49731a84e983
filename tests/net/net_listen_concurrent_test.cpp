// Two scanners at once (docs/dicom-network.md, "Several at once"): an association held open by
// a sender that went silent does not hold up another sender's series; two storescu writing into
// one series at the same moment both arrive whole; one association past `max_associations` is
// turned away at once as busy.
#include "net/net_harness.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcfilefo.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// A sender that opens an association and then says nothing: the node has accepted it (the
// A-ASSOCIATE-AC came back) and waits for its first command.
class SilentSender {
  public:
    SilentSender(int port, const std::string& calling) : fd_(connectLoopback(port)) {
        if (fd_ < 0) {
            throw std::runtime_error("cannot connect to the node");
        }
        const std::string rq = associateRequest(calling, "STEERSEG");
        ::send(fd_, rq.data(), rq.size(), MSG_NOSIGNAL);
        char type = 0;
        timeval wait{10, 0};
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
        accepted_ = ::recv(fd_, &type, 1, 0) == 1 && type == 0x02;
    }
    ~SilentSender() { ::close(fd_); }
    SilentSender(const SilentSender&) = delete;
    SilentSender& operator=(const SilentSender&) = delete;
    [[nodiscard]] bool accepted() const { return accepted_; }

  private:
    int fd_;
    bool accepted_ = false;
};

// storescu with its own timeouts well below the node's 30 s: a node that served one
// association at a time would leave it waiting behind the silent one until it failed.
Finished storescu(int port, const std::string& aet, const std::vector<fs::path>& files,
                  const fs::path& dir) {
    std::vector<std::string> argv{
        "storescu", "-aet", aet,  "-aec",      "STEERSEG",          "-to", "10", "-ta",
        "10",       "-td",  "10", "127.0.0.1", std::to_string(port)};
    for (const fs::path& f : files) {
        argv.push_back(f.string());
    }
    return runProgram(argv, dir);
}

std::vector<fs::path> seriesFiles(const fs::path& series) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(series)) {
        files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

class NetListenConcurrent : public ::testing::Test {
  protected:
    void SetUp() override {
        STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
        STEERSEG_REQUIRE_PROGRAM("/usr/bin/echoscu", "dcmtk");
        STEERSEG_REQUIRE_DATA(folder, "lung-ct-ibsi/dicom/image");
        series = seriesFiles(folder);
    }
    std::vector<fs::path> series;
};

TEST_F(NetListenConcurrent, ASilentSenderDoesNotHoldUpAnother) {
    const fs::path dir = tempDir("net-listen-silent");
    ListenProcess node(dir, {"--allow", "SCANNER", "--allow", "STALLED"});
    {
        const SilentSender stalled(node.port, "STALLED");
        ASSERT_TRUE(stalled.accepted()) << node.log();
        const auto start = std::chrono::steady_clock::now();
        const Finished pushed = storescu(node.port, "SCANNER", series, dir);
        EXPECT_EQ(pushed.status, 0) << pushed.output << node.log();
        EXPECT_LT(std::chrono::steady_clock::now() - start, 20s);
        EXPECT_EQ(filesBelow(dir / "store").size(), series.size()) << node.log();
    }
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

// Connections that say nothing, and connections that send half an association request and
// stop (a port scanner, a health check, a broken client; issue 48): fifty of the first and ten of
// the second open at once hold up nobody. A scanner's echo is answered within 2 s, and its
// series arrives whole within storescu's own 10 s timeouts.
TEST_F(NetListenConcurrent, SilentAndHalfSpokenConnectionsDoNotStallTheNode) {
    const fs::path dir = tempDir("net-listen-idle");
    ListenProcess node(dir, {"--allow", "SCANNER"});
    const std::string rq = associateRequest("SCANNER", "STEERSEG");
    std::vector<int> idle;
    for (int n = 0; n < 60; ++n) {
        const int fd = connectLoopback(node.port);
        ASSERT_GE(fd, 0);
        if (n >= 50) {
            ::send(fd, rq.data(), rq.size() / 2, MSG_NOSIGNAL);
        }
        idle.push_back(fd);
    }
    const auto start = std::chrono::steady_clock::now();
    const Finished echo = node.echo("SCANNER");
    EXPECT_EQ(echo.status, 0) << echo.output << node.log();
    EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
    const Finished pushed = storescu(node.port, "SCANNER", series, dir);
    EXPECT_EQ(pushed.status, 0) << pushed.output << node.log();
    EXPECT_EQ(filesBelow(dir / "store").size(), series.size()) << node.log();
    for (const int fd : idle) {
        ::close(fd);
    }
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

// SIGTERM with an association open and silent (issue 48): the node ends it and exits within
// 2 s, not after the peer's 30 s timeout.
TEST_F(NetListenConcurrent, AStopEndsTheOpenAssociationsAtOnce) {
    const fs::path dir = tempDir("net-listen-stop");
    ListenProcess node(dir, {"--allow", "STALLED"});
    const SilentSender stalled(node.port, "STALLED");
    ASSERT_TRUE(stalled.accepted()) << node.log();
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(node.process->stop(), 0) << node.log();
    EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
    fs::remove_all(dir);
}

// Each half of the series from its own scanner at the same moment, into the same series
// folder: every file whole, no temporary left.
TEST_F(NetListenConcurrent, TwoSendersIntoOneSeriesBothArriveWhole) {
    const fs::path dir = tempDir("net-listen-two");
    ListenProcess node(dir, {"--allow", "CT1", "--allow", "CT2"});
    const auto half = series.begin() + static_cast<std::ptrdiff_t>(series.size() / 2);
    Finished first;
    std::thread other([&] { first = storescu(node.port, "CT1", {series.begin(), half}, dir); });
    const Finished second = storescu(node.port, "CT2", {half, series.end()}, dir);
    other.join();
    EXPECT_EQ(first.status, 0) << first.output;
    EXPECT_EQ(second.status, 0) << second.output;
    const std::vector<fs::path> stored = filesBelow(dir / "store");
    ASSERT_EQ(stored.size(), series.size()) << node.log();
    EXPECT_EQ(stored.front().parent_path(), stored.back().parent_path());
    for (const fs::path& f : stored) {
        DcmFileFormat file;
        EXPECT_TRUE(file.loadFile(f.c_str()).good()) << f;
    }
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

// `max_associations = 1` with one association open: the next caller hears "busy" at once
// (rejected, transient), and is served once the first has gone.
TEST_F(NetListenConcurrent, OneAssociationPastTheMaximumIsTurnedAwayAsBusy) {
    const fs::path dir = tempDir("net-listen-busy");
    std::ofstream(dir / "node.toml") << "[dicom]\nmax_associations = 1\n"
                                        "[[dicom.peers]]\nname = \"ct\"\naet = \"SCANNER\"\n"
                                        "host = \"ct\"\nreceive = true\n";
    ListenProcess node(dir, {"--config", (dir / "node.toml").string()});
    {
        const SilentSender stalled(node.port, "SCANNER");
        ASSERT_TRUE(stalled.accepted()) << node.log();
        const Finished busy = node.echo("SCANNER");
        EXPECT_NE(busy.status, 0) << busy.output;
        EXPECT_TRUE(waitUntil(
            [&] {
                return node.log().find("1 association(s) open already (busy)") != std::string::npos;
            },
            5s))
            << node.log();
    }
    // The silent one's connection closed: its thread ends and the slot is free again.
    EXPECT_TRUE(waitUntil([&] { return node.echo("SCANNER").status == 0; }, 10s)) << node.log();
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
