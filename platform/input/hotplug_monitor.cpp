#include "platform/input/hotplug_monitor.hpp"

#include "platform/input/node_access.hpp"

#include <algorithm>
#include <cstdio>
#include <libudev.h>
#include <unistd.h>

namespace steerseg::platform::input {

struct HotplugMonitor::Udev {
    udev* context = nullptr;
    udev_monitor* monitor = nullptr;
    ~Udev() {
        if (monitor != nullptr) {
            udev_monitor_unref(monitor);
        }
        if (context != nullptr) {
            udev_unref(context);
        }
    }
};

namespace {

constexpr const char* kSubsystems[] = {"hidraw", "input", "gpio"};

} // namespace

HotplugMonitor::HotplugMonitor(const HotplugOptions& options) : options_(options) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", options_.rescanSeconds);
    const std::string fallback =
        ": rescanning " + options_.devDir + " every " + seconds + " s instead";
    if (!options_.useUdev) {
        notice_ = "hotplug: udev monitor not requested" + fallback;
        return;
    }
    // Without udevd the netlink socket opens but never hears anything: check it runs.
    if (::access("/run/udev/control", F_OK) != 0) {
        notice_ = "hotplug: udev is not running (no /run/udev/control)" + fallback;
        return;
    }
    auto u = std::make_unique<Udev>();
    u->context = udev_new();
    if (u->context == nullptr) {
        notice_ = "hotplug: udev_new failed" + fallback;
        return;
    }
    u->monitor = udev_monitor_new_from_netlink(u->context, "udev");
    if (u->monitor == nullptr) {
        notice_ = "hotplug: udev_monitor_new_from_netlink failed" + fallback;
        return;
    }
    for (const char* subsystem : kSubsystems) {
        if (udev_monitor_filter_add_match_subsystem_devtype(u->monitor, subsystem, nullptr) < 0) {
            notice_ = std::string("hotplug: udev filter for ") + subsystem + " failed" + fallback;
            return;
        }
    }
    if (udev_monitor_enable_receiving(u->monitor) < 0) {
        notice_ = "hotplug: udev_monitor_enable_receiving failed" + fallback;
        return;
    }
    udev_ = std::move(u);
}

HotplugMonitor::~HotplugMonitor() = default;

int HotplugMonitor::fd() const {
    return udev_ ? udev_monitor_get_fd(udev_->monitor) : -1;
}

bool HotplugMonitor::usingUdev() const {
    return udev_ != nullptr;
}

std::string HotplugMonitor::takeNotice() {
    std::string notice;
    notice.swap(notice_);
    return notice;
}

void HotplugMonitor::poll(double now, std::vector<HotplugChange>& out) {
    if (!udev_) {
        if (now >= nextRescan_) {
            nextRescan_ = now + options_.rescanSeconds;
            rescan(out);
        }
        return;
    }
    // The socket is non-blocking: receive returns null once drained.
    while (udev_device* device = udev_monitor_receive_device(udev_->monitor)) {
        const char* action = udev_device_get_action(device);
        const char* node = udev_device_get_devnode(device);
        const char* subsystem = udev_device_get_subsystem(device);
        // input's parent devices (input/input12) have no node; only their eventN children do.
        if (action != nullptr && node != nullptr && subsystem != nullptr) {
            const std::string what = action;
            if (what == "add" || what == "remove") {
                HotplugChange change;
                change.action =
                    what == "add" ? HotplugChange::Action::Added : HotplugChange::Action::Removed;
                change.subsystem = subsystem;
                change.devnode = node;
                out.push_back(std::move(change));
            }
        }
        udev_device_unref(device);
    }
}

void HotplugMonitor::rescan(std::vector<HotplugChange>& out) {
    std::vector<HotplugChange> seen;
    const auto add = [&seen](const std::string& subsystem, const std::vector<std::string>& nodes) {
        for (const std::string& node : nodes) {
            seen.push_back({HotplugChange::Action::Added, subsystem, node});
        }
    };
    add("hidraw", listNodes(options_.devDir, "hidraw"));
    add("input", listNodes(options_.devDir + "/input", "event"));
    add("gpio", listNodes(options_.devDir, "gpiochip"));
    const auto contains = [](const std::vector<HotplugChange>& list, const HotplugChange& c) {
        return std::any_of(list.begin(), list.end(),
                           [&c](const HotplugChange& x) { return x.devnode == c.devnode; });
    };
    for (const HotplugChange& old : known_) {
        if (!contains(seen, old)) {
            out.push_back({HotplugChange::Action::Removed, old.subsystem, old.devnode});
        }
    }
    for (const HotplugChange& now : seen) {
        if (!contains(known_, now)) {
            out.push_back(now);
        }
    }
    known_ = std::move(seen);
}

} // namespace steerseg::platform::input
