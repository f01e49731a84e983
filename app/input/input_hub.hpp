#pragma once

// The kiosk's owner of the input devices (docs/input-devices.md): the configured devices'
// sources, one decoder each, and the control bindings. Each frame it reads every source without
// blocking (a bounded number of records), feeds the records through the device's decoder and
// the bindings, and hands back workflow actions. Replayed records (a recording, a script's raw
// lines) go through the same decoders. A device that fails, floods or sends garbage gets log
// lines (at most one per device per second) and is capped or skipped; one that goes away is
// reset (held buttons released, rings at rest), shown disconnected and opened again later.
#include "config/kiosk_config.hpp"
#include "input/control_bindings.hpp"
#include "model/action.hpp"
#include "platform/input/decoder.hpp"
#include "platform/input/device_spec.hpp"
#include "platform/input/raw_source.hpp"
#include "workflow/status.hpp"

#include <cstddef>
#include <deque>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace steerseg::input {

// [[input.devices]] -> the platform's specs (config may not include platform/).
platform::input::DeviceSpec deviceSpec(const config::InputDeviceConfig& device);
std::vector<platform::input::DeviceSpec>
deviceSpecs(const std::vector<config::InputDeviceConfig>& devices);

// The LED's meaning: steady while evolving, pulsing while paused, off otherwise.
platform::input::Indicator indicatorFor(model::State state);

struct InputHubLimits {
    std::size_t recordsPerFrame = 256;   // per device: a flood cannot stall a frame
    std::size_t recordsPerSecond = 2000; // per device: beyond this the rest of the second is
                                         // dropped (a knob sends at most a few hundred)
    double retrySeconds = 2.0;           // a missing or unplugged device is opened again
    double logSeconds = 1.0;             // at most one problem line per device this often
    std::string logPrefix;               // before each line's "input: " ("steerseg kiosk: ")
};

class InputHub {
  public:
    // How devices are opened and decoded: the live ones (input_hub_live.cpp: openSource and
    // makeDecoder of platform/input) or a test's.
    struct Backend {
        std::function<std::unique_ptr<platform::input::RawSource>(
            const platform::input::DeviceSpec&, std::string& problem)>
            open;
        std::function<std::unique_ptr<platform::input::Decoder>(const platform::input::DeviceSpec&)>
            decoder;
        // Whether devices came or went since the last call (the hotplug monitor); missing
        // devices are then opened at once instead of at their next retry. May be empty.
        std::function<bool(double now)> devicesChanged;
    };
    // What one control event became, for input-monitor.
    using EventObserver = std::function<void(const platform::input::ControlEvent&,
                                             const std::vector<model::Action>&)>;

    // `log` gets one line per problem ("input: shuttle: ..."). `live`: open the devices and
    // retry them; false for a replay, where only replayed records arrive.
    InputHub(std::vector<platform::input::DeviceSpec> specs, ControlBindings bindings,
             Backend backend, bool live, std::ostream& log, InputHubLimits limits = {});
    ~InputHub();
    InputHub(const InputHub&) = delete;
    InputHub& operator=(const InputHub&) = delete;

    // One frame at `now` (seconds, the clock records are stamped with): reads the sources,
    // opens missing ones when their retry is due, delivers replayed records that are due, lets
    // the decoders and the rings' repeats tick. Appends the actions.
    void poll(double now, std::vector<model::Action>& out);
    // One raw record from a replay or a script, on the hub's clock, through its device's decoder.
    void inject(const platform::input::RawRecord& record, std::vector<model::Action>& out);
    // A whole recording, replayed in time: its first record at `now`, the others as far apart
    // as they were recorded (poll() delivers them).
    void replay(std::vector<platform::input::RawRecord> records, double now);
    [[nodiscard]] bool replaying() const { return !pending_.empty(); }
    // The LEDs follow the workflow; sent to a source when it changes and when it reconnects.
    void setIndicator(platform::input::Indicator indicator);

    // Each configured device that takes input or shows an indicator, connected or not.
    [[nodiscard]] std::vector<workflow::DeviceLink> links() const;
    // Whether something still moves without new input (a ring off centre, a replay).
    [[nodiscard]] bool busy() const;
    void setObserver(EventObserver observer) { observer_ = std::move(observer); }
    [[nodiscard]] const ControlBindings& bindings() const { return bindings_; }
    // Every raw record a device delivered (its unplug and replug as Unplugged/Plugged records),
    // for input-monitor --record.
    using RecordObserver = std::function<void(const platform::input::RawRecord&)>;
    void setRecordObserver(RecordObserver observer) { recordObserver_ = std::move(observer); }

  private:
    struct Device;

    Device* find(const std::string& name);
    void openDue(double now);
    void readSource(Device& d, double now, std::vector<model::Action>& out);
    void feed(Device& d, const platform::input::RawRecord& record, std::vector<model::Action>& out);
    void unplugged(Device& d, double now, const std::string& why, std::vector<model::Action>& out);
    void deliver(std::vector<platform::input::ControlEvent>& events,
                 std::vector<model::Action>& out);
    void problem(Device& d, double now, const std::string& line);
    void takeProblems(Device& d, double now);

    std::vector<std::unique_ptr<Device>> devices_;
    ControlBindings bindings_;
    Backend backend_;
    bool live_;
    std::ostream& log_;
    InputHubLimits limits_;
    platform::input::Indicator indicator_ = platform::input::Indicator::Off;
    std::deque<platform::input::RawRecord> pending_; // a replay, on the hub's clock
    double replayOffset_ = 0.0;
    double unknownLogged_ = -1e9; // records naming no configured device: one line a second
    std::size_t unknownHeld_ = 0;
    std::vector<platform::input::RawRecord> records_;   // reused each frame
    std::vector<platform::input::ControlEvent> events_; // reused each frame
    EventObserver observer_;
    RecordObserver recordObserver_;
};

} // namespace steerseg::input
