#include "input/input_backend.hpp"

#include "platform/input/decoders.hpp"
#include "platform/input/hotplug_monitor.hpp"
#include "platform/input/sources.hpp"

#include <memory>
#include <ostream>

namespace steerseg::input {

InputHub::Backend liveInputBackend(std::ostream& log, const std::string& prefix) {
    InputHub::Backend backend = replayInputBackend();
    backend.open = [](const platform::input::DeviceSpec& spec, std::string& problem) {
        return platform::input::openSource(spec, problem);
    };
    // Shared by the copies std::function makes; the monitor lives as long as the hub's backend.
    auto monitor = std::make_shared<platform::input::HotplugMonitor>();
    auto changes = std::make_shared<std::vector<platform::input::HotplugChange>>();
    backend.devicesChanged = [monitor, changes, &log, prefix](double now) {
        changes->clear();
        monitor->poll(now, *changes);
        if (const std::string notice = monitor->takeNotice(); !notice.empty()) {
            log << prefix << "input: " << notice << '\n';
        }
        return !changes->empty();
    };
    return backend;
}

InputHub::Backend replayInputBackend() {
    InputHub::Backend backend;
    backend.decoder = [](const platform::input::DeviceSpec& spec) {
        return platform::input::makeDecoder(spec);
    };
    return backend;
}

} // namespace steerseg::input
