#pragma once

// systemd's service notification protocol (sd_notify(3)) for a Type=notify unit: READY=1 once
// the service does its job, STATUS= lines for `systemctl status`, WATCHDOG=1 keep-alives and
// STOPPING=1. Outside systemd (no NOTIFY_SOCKET) every call does nothing.
#include <chrono>
#include <optional>
#include <string_view>

namespace steerseg::platform {

class ServiceNotifier {
  public:
    using Clock = std::chrono::steady_clock;

    // Reads NOTIFY_SOCKET, WATCHDOG_USEC and WATCHDOG_PID once, as libsystemd does.
    ServiceNotifier();

    // Whether a service manager listens (NOTIFY_SOCKET is set).
    [[nodiscard]] bool listening() const { return listening_; }
    // The unit's WatchdogSec for this process, when its watchdog is on.
    [[nodiscard]] std::optional<std::chrono::microseconds> watchdogInterval() const {
        return watchdog_;
    }

    void ready(std::string_view status);
    void status(std::string_view status);
    // Sends WATCHDOG=1 when half the interval has passed since the last one (or none was
    // sent), so one late frame does not cost the service its life.
    void keepAlive(Clock::time_point now);
    void stopping();

  private:
    void send(const char* fields, std::string_view status);

    bool listening_ = false;
    std::optional<std::chrono::microseconds> watchdog_;
    std::optional<Clock::time_point> lastKeepAlive_;
};

} // namespace steerseg::platform
