// platform::ServiceNotifier against a real notification socket: what systemd would receive,
// the watchdog's pacing, and silence without NOTIFY_SOCKET.
#include "platform/systemd/service_notifier.hpp"
#include "support/notify_socket.hpp"
#include "support/test_data.hpp"

#include <cstdlib>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace steerseg::test {
namespace {

using namespace std::chrono_literals;
using Clock = platform::ServiceNotifier::Clock;

class ServiceNotifierTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ::unsetenv("WATCHDOG_PID");
        ::unsetenv("WATCHDOG_USEC");
        ::setenv("NOTIFY_SOCKET", socket.path().c_str(), 1);
    }
    void TearDown() override {
        ::unsetenv("NOTIFY_SOCKET");
        ::unsetenv("WATCHDOG_USEC");
        ::unsetenv("WATCHDOG_PID");
    }
    NotifySocket socket{tempDir("service-notifier")};
};

TEST_F(ServiceNotifierTest, SendsReadyStatusAndStopping) {
    platform::ServiceNotifier n;
    EXPECT_TRUE(n.listening());
    EXPECT_FALSE(n.watchdogInterval().has_value());
    n.ready("seeding");
    n.status("evolving: two\nlines");
    n.stopping();
    const auto got = socket.receive();
    ASSERT_EQ(got.size(), 3U);
    EXPECT_EQ(got[0], "READY=1\nSTATUS=seeding");
    EXPECT_EQ(got[1], "STATUS=evolving: two lines");
    EXPECT_EQ(got[2], "STOPPING=1");
}

TEST_F(ServiceNotifierTest, KeepAliveAtHalfTheWatchdogInterval) {
    ::setenv("WATCHDOG_USEC", "2000000", 1);
    platform::ServiceNotifier n;
    ASSERT_EQ(n.watchdogInterval(), std::chrono::microseconds(2000000));
    const Clock::time_point t0 = Clock::now();
    n.keepAlive(t0);          // the first: sent
    n.keepAlive(t0 + 500ms);  // a quarter in: not yet
    n.keepAlive(t0 + 999ms);  // just under half: not yet
    n.keepAlive(t0 + 1000ms); // half: sent
    n.keepAlive(t0 + 1500ms); // half of it since the last: not yet
    n.keepAlive(t0 + 2100ms); // sent
    const auto got = socket.receive();
    EXPECT_EQ(got, (std::vector<std::string>{"WATCHDOG=1", "WATCHDOG=1", "WATCHDOG=1"}));
}

TEST_F(ServiceNotifierTest, WatchdogOfAnotherProcessIsNotFed) {
    ::setenv("WATCHDOG_USEC", "2000000", 1);
    ::setenv("WATCHDOG_PID", std::to_string(::getpid() + 1).c_str(), 1);
    platform::ServiceNotifier n;
    EXPECT_FALSE(n.watchdogInterval().has_value());
    n.keepAlive(Clock::now());
    EXPECT_TRUE(socket.receive().empty());
}

TEST_F(ServiceNotifierTest, SilentWithoutNotifySocket) {
    ::unsetenv("NOTIFY_SOCKET");
    ::setenv("WATCHDOG_USEC", "2000000", 1);
    platform::ServiceNotifier n;
    EXPECT_FALSE(n.listening());
    n.ready("x");
    n.keepAlive(Clock::now());
    n.stopping();
    EXPECT_TRUE(socket.receive().empty());
}

} // namespace
} // namespace steerseg::test
