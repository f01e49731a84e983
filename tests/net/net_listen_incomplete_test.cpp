// A series cut off half way is listed as incomplete and never offered as if whole (issue 48;
// docs/dicom-network.md, "Whole or incomplete"): the node stopped (SIGTERM) or killed (kill -9)
// while storescu is half way through, the sender killed (its connection reset) or ending with an
// A-ABORT; the mark survives a restart of the node, and a later complete send of the series makes
// it whole again.
#include "net/net_harness.hpp"
#include "net/received_series.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <csignal>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

std::size_t countOf(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

class NetListenIncomplete : public ::testing::Test {
  protected:
    void SetUp() override {
        STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
        STEERSEG_REQUIRE_DATA(folder, "lung-ct-ibsi/dicom/image");
        for (const auto& e : fs::directory_iterator(folder)) {
            series.push_back(e.path().string());
        }
        std::sort(series.begin(), series.end());
    }

    // storescu sending the series twenty times over (1200 C-STOREs into the same 60 files),
    // frozen (SIGSTOP) once the node has stored a few: an association half way, for as long
    // as the test wants.
    std::unique_ptr<ChildProcess> frozenSender(const ListenProcess& node) const {
        std::vector<std::string> argv{"storescu",
                                      "-aet",
                                      "SCANNER",
                                      "-aec",
                                      "STEERSEG",
                                      "127.0.0.1",
                                      std::to_string(node.port)};
        for (int round = 0; round < 20; ++round) {
            argv.insert(argv.end(), series.begin(), series.end());
        }
        auto sender = std::make_unique<ChildProcess>(argv, node.dir / "sender.log");
        const bool started = waitUntil([&] { return countOf(node.log(), "stored ") >= 3; }, 20s);
        sender->signal(SIGSTOP);
        EXPECT_TRUE(started) << node.log() << sender->log();
        return sender;
    }

    static void killSender(std::unique_ptr<ChildProcess>& sender) {
        sender->killHard();
        sender->stop(); // reaps it
        sender.reset();
    }

    // The one series in the store, as the kiosk's load screen lists it.
    static net::ReceivedSeries listed(const fs::path& store) {
        const auto list = net::listReceivedSeries(store, std::chrono::seconds(0));
        EXPECT_EQ(list.size(), 1U);
        return list.empty() ? net::ReceivedSeries{} : list.front();
    }

    // A new `steerseg listen` over the same store, with a log of its own.
    static std::unique_ptr<ListenProcess> restarted(std::unique_ptr<ListenProcess> old) {
        const fs::path dir = old->dir;
        old.reset();
        fs::remove(dir / "listen.log");
        return std::make_unique<ListenProcess>(dir, std::vector<std::string>{"--allow", "SCANNER"});
    }

    static std::size_t marksIn(const fs::path& store) {
        std::size_t n = 0;
        for (const fs::path& f : filesBelow(store)) {
            n += f.filename().string().rfind(".receiving-", 0) == 0 ? 1 : 0;
        }
        return n;
    }

    // A complete send of the whole series, then the listing says whole again.
    void expectWholeAfterACompleteSend(const ListenProcess& node) const {
        const Finished whole =
            node.storescu("SCANNER", series.front().substr(0, series.front().rfind('/')));
        ASSERT_EQ(whole.status, 0) << whole.output << node.log();
        const net::ReceivedSeries s = listed(node.dir / "store");
        EXPECT_FALSE(s.incomplete) << node.log();
        EXPECT_EQ(s.images, static_cast<int>(series.size()));
        EXPECT_EQ(net::describe(s).find("incomplete"), std::string::npos) << net::describe(s);
        EXPECT_EQ(marksIn(node.dir / "store"), 0U);
    }

    std::vector<std::string> series;
};

// SIGTERM with an association half way: the node exits within 2 s (status 0), says which series
// it left incomplete, and the listing says so, after a restart too.
TEST_F(NetListenIncomplete, AStopHalfWayLeavesTheSeriesIncompleteUntilACompleteSend) {
    const fs::path dir = tempDir("net-listen-incomplete-stop");
    auto node =
        std::make_unique<ListenProcess>(dir, std::vector<std::string>{"--allow", "SCANNER"});
    auto sender = frozenSender(*node);
    {
        // While the association is open, the series is arriving, never whole.
        const net::ReceivedSeries s = listed(dir / "store");
        EXPECT_TRUE(s.arriving);
        EXPECT_LT(s.images, static_cast<int>(series.size()));
    }
    const auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(node->process->stop(), 0) << node->log();
    const auto took = std::chrono::steady_clock::now() - start;
    EXPECT_LT(took, 2s) << node->log();
    std::printf("SIGTERM with an association half way: exited in %.2f s\n",
                std::chrono::duration<double>(took).count());
    EXPECT_TRUE(
        waitUntil([&] { return node->log().find("incomplete series ") != std::string::npos; }, 5s))
        << node->log();
    EXPECT_NE(node->log().find("the node stopped before"), std::string::npos) << node->log();
    killSender(sender);
    {
        const net::ReceivedSeries s = listed(dir / "store");
        EXPECT_TRUE(s.incomplete);
        EXPECT_FALSE(s.arriving);
        EXPECT_NE(net::describe(s).find(" - incomplete"), std::string::npos) << net::describe(s);
    }
    // A new run of the node says so at its start, and still lists it so.
    node = restarted(std::move(node));
    EXPECT_TRUE(
        waitUntil([&] { return node->log().find("incomplete series ") != std::string::npos; }, 5s))
        << node->log();
    EXPECT_TRUE(listed(dir / "store").incomplete);
    expectWholeAfterACompleteSend(*node);
    EXPECT_EQ(node->process->stop(), 0);
    fs::remove_all(dir);
}

// kill -9 of the node half way: nothing runs at the kill, the mark on disk says it all.
TEST_F(NetListenIncomplete, AKilledNodeLeavesTheSeriesIncomplete) {
    const fs::path dir = tempDir("net-listen-incomplete-kill");
    auto node =
        std::make_unique<ListenProcess>(dir, std::vector<std::string>{"--allow", "SCANNER"});
    auto sender = frozenSender(*node);
    node->process->killHard();
    node->process->stop();
    killSender(sender);
    EXPECT_TRUE(listed(dir / "store").incomplete);
    node = restarted(std::move(node));
    EXPECT_TRUE(
        waitUntil([&] { return node->log().find("incomplete series ") != std::string::npos; }, 5s))
        << node->log();
    expectWholeAfterACompleteSend(*node);
    EXPECT_EQ(node->process->stop(), 0);
    fs::remove_all(dir);
}

// The sender killed half way (its connection reset under the association): the node goes on,
// says so, and the series is incomplete.
TEST_F(NetListenIncomplete, ASenderCutOffHalfWayLeavesTheSeriesIncomplete) {
    const fs::path dir = tempDir("net-listen-incomplete-reset");
    ListenProcess node(dir, {"--allow", "SCANNER"});
    auto sender = frozenSender(node);
    killSender(sender);
    EXPECT_TRUE(
        waitUntil([&] { return node.log().find("incomplete series ") != std::string::npos; }, 10s))
        << node.log();
    const net::ReceivedSeries s = listed(dir / "store");
    EXPECT_TRUE(s.incomplete);
    EXPECT_FALSE(s.arriving);
    expectWholeAfterACompleteSend(node);
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

// storescu --abort: half the series, then an A-ABORT instead of the release.
TEST_F(NetListenIncomplete, AnAbortAfterHalfTheSeriesLeavesItIncomplete) {
    const fs::path dir = tempDir("net-listen-incomplete-abort");
    ListenProcess node(dir, {"--allow", "SCANNER"});
    std::vector<std::string> argv{"storescu", "--abort",  "-aet",      "SCANNER",
                                  "-aec",     "STEERSEG", "127.0.0.1", std::to_string(node.port)};
    argv.insert(argv.end(), series.begin(),
                series.begin() + static_cast<std::ptrdiff_t>(series.size() / 2));
    const Finished half = runProgram(argv, dir);
    EXPECT_EQ(half.status, 0) << half.output;
    EXPECT_TRUE(
        waitUntil([&] { return node.log().find("incomplete series ") != std::string::npos; }, 10s))
        << node.log();
    EXPECT_NE(node.log().find("aborted by the sender"), std::string::npos) << node.log();
    const net::ReceivedSeries s = listed(dir / "store");
    EXPECT_TRUE(s.incomplete);
    EXPECT_EQ(s.images, static_cast<int>(series.size() / 2));
    expectWholeAfterACompleteSend(node);
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
