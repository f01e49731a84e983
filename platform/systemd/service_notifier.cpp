#include "platform/systemd/service_notifier.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <systemd/sd-daemon.h>

namespace steerseg::platform {

ServiceNotifier::ServiceNotifier() {
    const char* socket = std::getenv("NOTIFY_SOCKET");
    listening_ = socket != nullptr && *socket != '\0';
    std::uint64_t usec = 0;
    // > 0 only when WATCHDOG_USEC is set and WATCHDOG_PID, if set, names this process: a child
    // the kiosk might start must not feed its parent's watchdog.
    if (sd_watchdog_enabled(0, &usec) > 0 && usec > 0) {
        watchdog_ = std::chrono::microseconds(static_cast<std::int64_t>(usec));
    }
}

void ServiceNotifier::ready(std::string_view status) {
    send("READY=1\n", status);
}

void ServiceNotifier::status(std::string_view status) {
    send("", status);
}

void ServiceNotifier::keepAlive(Clock::time_point now) {
    if (!watchdog_ || (lastKeepAlive_ && now - *lastKeepAlive_ < *watchdog_ / 2)) {
        return;
    }
    lastKeepAlive_ = now;
    send("WATCHDOG=1", "");
}

void ServiceNotifier::stopping() {
    send("STOPPING=1\n", "");
}

// A failed send is not the kiosk's problem: the service manager notices the missing READY or
// keep-alive itself, and a kiosk without systemd must run on.
void ServiceNotifier::send(const char* fields, std::string_view status) {
    if (!listening_) {
        return;
    }
    std::string message = fields;
    if (!status.empty()) {
        // One line: a newline would start a field of its own.
        std::string line(status);
        for (char& c : line) {
            if (c == '\n' || c == '\r') {
                c = ' ';
            }
        }
        message += "STATUS=" + line;
    }
    if (!message.empty() && message.back() == '\n') {
        message.pop_back();
    }
    sd_notify(0, message.c_str());
}

} // namespace steerseg::platform
