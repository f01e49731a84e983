#pragma once

// Devices coming and going: a libudev monitor on the hidraw, input and gpio subsystems, read
// without blocking. Where udev is not running (a container, an early boot), the monitor says
// so once and rescans the device directories every few seconds instead, reporting the nodes
// that appeared or vanished; the owner then calls openSource again for missing devices.
#include <memory>
#include <string>
#include <vector>

namespace steerseg::platform::input {

struct HotplugChange {
    enum class Action { Added, Removed };
    Action action = Action::Added;
    std::string subsystem; // "hidraw", "input", "gpio"
    std::string devnode;   // "/dev/hidraw3", "/dev/input/event7", "/dev/gpiochip0"
};

struct HotplugOptions {
    bool useUdev = true;         // false forces the rescan (tests)
    std::string devDir = "/dev"; // where the rescan looks (hidraw*, input/event*, gpiochip*)
    double rescanSeconds = 2.0;
};

class HotplugMonitor {
  public:
    explicit HotplugMonitor(const HotplugOptions& options = {});
    ~HotplugMonitor();
    HotplugMonitor(const HotplugMonitor&) = delete;
    HotplugMonitor& operator=(const HotplugMonitor&) = delete;

    // udev's socket to poll() for changes; -1 when rescanning (call poll each frame).
    [[nodiscard]] int fd() const;
    [[nodiscard]] bool usingUdev() const;
    // Appends the changes since the last call; `now` (seconds, any monotonic clock) paces the
    // rescan.
    void poll(double now, std::vector<HotplugChange>& out);
    // Why udev is not used, once ("hotplug: udev is not running (no /run/udev): rescanning
    // /dev every 2 s"); empty after the first call or when udev is in use.
    std::string takeNotice();

  private:
    struct Udev;
    void rescan(std::vector<HotplugChange>& out);
    HotplugOptions options_;
    std::unique_ptr<Udev> udev_;
    std::vector<HotplugChange> known_; // the rescan's last view (Added entries)
    double nextRescan_ = -1e300;
    std::string notice_;
};

} // namespace steerseg::platform::input
