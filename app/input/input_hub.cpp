#include "input/input_hub.hpp"

#include <algorithm>
#include <ostream>
#include <utility>

namespace steerseg::input {

namespace {

using platform::input::ControlEvent;
using platform::input::DeviceSpec;
using platform::input::Indicator;
using platform::input::RawRecord;
using platform::input::RawSource;

std::string kindName(DeviceSpec::Kind kind) {
    switch (kind) {
    case DeviceSpec::Kind::Shuttle:
        return "shuttle";
    case DeviceSpec::Kind::Radial:
        return "radial";
    case DeviceSpec::Kind::PowerMate:
        return "powermate";
    case DeviceSpec::Kind::GpioInput:
        return "gpio_input";
    case DeviceSpec::Kind::GpioLed:
        return "gpio_led";
    }
    return "?";
}

} // namespace

DeviceSpec deviceSpec(const config::InputDeviceConfig& d) {
    DeviceSpec s;
    switch (d.kind) {
    case config::InputDeviceKind::Shuttle:
        s.kind = DeviceSpec::Kind::Shuttle;
        break;
    case config::InputDeviceKind::Radial:
        s.kind = DeviceSpec::Kind::Radial;
        break;
    case config::InputDeviceKind::PowerMate:
        s.kind = DeviceSpec::Kind::PowerMate;
        break;
    case config::InputDeviceKind::GpioInput:
        s.kind = DeviceSpec::Kind::GpioInput;
        break;
    case config::InputDeviceKind::GpioLed:
        s.kind = DeviceSpec::Kind::GpioLed;
        break;
    }
    s.name = d.name;
    s.vendorId = static_cast<std::uint16_t>(d.vendorId);
    s.productId = static_cast<std::uint16_t>(d.productId);
    s.usagePage = static_cast<std::uint16_t>(d.usagePage);
    s.usage = static_cast<std::uint16_t>(d.usage);
    s.path = d.path;
    s.chip = d.chip;
    s.line = d.line;
    s.activeLow = d.activeLow;
    s.debounceSeconds = d.debounceMs * 1e-3;
    return s;
}

std::vector<DeviceSpec> deviceSpecs(const std::vector<config::InputDeviceConfig>& devices) {
    std::vector<DeviceSpec> specs;
    specs.reserve(devices.size());
    for (const config::InputDeviceConfig& d : devices) {
        specs.push_back(deviceSpec(d));
    }
    return specs;
}

Indicator indicatorFor(model::State state) {
    switch (state) {
    case model::State::Evolving:
        return Indicator::Steady;
    case model::State::Paused:
        return Indicator::Pulsing;
    default:
        return Indicator::Off;
    }
}

struct InputHub::Device {
    DeviceSpec spec;
    std::unique_ptr<platform::input::Decoder> decoder; // nullptr: an output (LED)
    std::unique_ptr<RawSource> source;
    bool connected = false;
    bool everOpened = false;
    double nextOpen = 0.0;
    std::string lastOpenProblem; // logged once until it changes
    // The rate-limited log.
    double lastLog = -1e9;
    std::size_t heldProblems = 0;
    // The flood cap, per second of record time.
    double windowStart = -1e9;
    std::size_t windowRecords = 0;
    std::size_t dropped = 0;
};

InputHub::InputHub(std::vector<DeviceSpec> specs, ControlBindings bindings, Backend backend,
                   bool live, std::ostream& log, InputHubLimits limits)
    : bindings_(std::move(bindings)), backend_(std::move(backend)), live_(live), log_(log),
      limits_(limits) {
    for (DeviceSpec& spec : specs) {
        auto d = std::make_unique<Device>();
        d->decoder = backend_.decoder ? backend_.decoder(spec) : nullptr;
        d->spec = std::move(spec);
        devices_.push_back(std::move(d));
    }
}

InputHub::~InputHub() = default;

InputHub::Device* InputHub::find(const std::string& name) {
    for (auto& d : devices_) {
        if (d->spec.name == name) {
            return d.get();
        }
    }
    return nullptr;
}

void InputHub::problem(Device& d, double now, const std::string& line) {
    if (now - d.lastLog < limits_.logSeconds) {
        ++d.heldProblems;
        return;
    }
    log_ << limits_.logPrefix << "input: " << line;
    if (d.heldProblems > 0) {
        log_ << " (and " << d.heldProblems << " more since the last line)";
    }
    log_ << '\n';
    d.lastLog = now;
    d.heldProblems = 0;
}

void InputHub::takeProblems(Device& d, double now) {
    if (!d.decoder) {
        return;
    }
    for (const std::string& p : d.decoder->takeProblems()) {
        problem(d, now, p);
    }
}

void InputHub::deliver(std::vector<ControlEvent>& events, std::vector<model::Action>& out) {
    for (const ControlEvent& e : events) {
        const std::size_t before = out.size();
        bindings_.feed(e, out);
        if (observer_) {
            observer_(e, std::vector<model::Action>(
                             out.begin() + static_cast<std::ptrdiff_t>(before), out.end()));
        }
    }
    events.clear();
}

void InputHub::unplugged(Device& d, double now, const std::string& why,
                         std::vector<model::Action>& out) {
    if (d.decoder) {
        d.decoder->reset(now, events_);
        deliver(events_, out);
    }
    if (d.connected || d.source) {
        // Not rate-limited: an unplug is news, and happens once per plug.
        log_ << limits_.logPrefix << "input: " << d.spec.name << ": disconnected"
             << (why.empty() ? "" : ": ") << why << '\n';
    }
    d.source.reset();
    d.connected = false;
    d.nextOpen = now + limits_.retrySeconds;
}

void InputHub::feed(Device& d, const RawRecord& record, std::vector<model::Action>& out) {
    if (recordObserver_) {
        recordObserver_(record);
    }
    if (record.kind == RawRecord::Kind::Unplugged) {
        unplugged(d, record.time, "", out);
        return;
    }
    if (record.kind == RawRecord::Kind::Plugged) {
        if (!d.connected) {
            log_ << limits_.logPrefix << "input: " << d.spec.name << ": connected\n";
        }
        d.connected = true;
        return;
    }
    if (!d.decoder) {
        problem(d, record.time, d.spec.name + ": takes no input; record skipped");
        return;
    }
    if (record.time - d.windowStart >= 1.0 || record.time < d.windowStart) {
        if (d.dropped > 0) {
            problem(d, record.time,
                    d.spec.name + ": " + std::to_string(d.dropped) +
                        " records dropped in a second (more than " +
                        std::to_string(limits_.recordsPerSecond) + " a second)");
        }
        d.windowStart = record.time;
        d.windowRecords = 0;
        d.dropped = 0;
    }
    if (++d.windowRecords > limits_.recordsPerSecond) {
        if (d.dropped++ == 0) {
            problem(d, record.time,
                    d.spec.name + ": flooding: more than " +
                        std::to_string(limits_.recordsPerSecond) +
                        " records a second; the rest of this second is dropped");
        }
        return;
    }
    d.decoder->feed(record, events_);
    deliver(events_, out);
}

void InputHub::inject(const RawRecord& record, std::vector<model::Action>& out) {
    Device* d = find(record.device);
    if (d == nullptr) {
        if (record.time - unknownLogged_ >= limits_.logSeconds) {
            log_ << limits_.logPrefix << "input: no configured device \"" << record.device
                 << "\"; record skipped";
            if (unknownHeld_ > 0) {
                log_ << " (and " << unknownHeld_ << " more)";
            }
            log_ << '\n';
            unknownLogged_ = record.time;
            unknownHeld_ = 0;
        } else {
            ++unknownHeld_;
        }
        return;
    }
    // A replayed device counts as connected from its first record (until an unplug record).
    if (!d->connected && record.kind != RawRecord::Kind::Unplugged) {
        d->connected = true;
    }
    feed(*d, record, out);
    takeProblems(*d, record.time);
}

void InputHub::replay(std::vector<RawRecord> records, double now) {
    if (records.empty()) {
        return;
    }
    replayOffset_ = now - records.front().time;
    pending_.assign(std::make_move_iterator(records.begin()),
                    std::make_move_iterator(records.end()));
}

void InputHub::openDue(double now) {
    for (auto& d : devices_) {
        if (d->source || now < d->nextOpen || !backend_.open) {
            continue;
        }
        std::string why;
        d->source = backend_.open(d->spec, why);
        d->nextOpen = now + limits_.retrySeconds;
        if (!d->source) {
            // "not found" every two seconds for a device a site does not have would fill the
            // log: a problem is logged when it first appears or changes.
            if (why != d->lastOpenProblem) {
                // The sources' problems start with the device's name.
                log_ << limits_.logPrefix << "input: " << why << '\n';
                d->lastOpenProblem = why;
            }
            continue;
        }
        d->lastOpenProblem.clear();
        d->connected = true;
        log_ << limits_.logPrefix << "input: " << d->spec.name << ": "
             << (d->everOpened ? "reconnected" : "connected") << '\n';
        if (d->everOpened && recordObserver_) {
            RawRecord back;
            back.kind = RawRecord::Kind::Plugged;
            back.time = now;
            back.device = d->spec.name;
            recordObserver_(back);
        }
        d->everOpened = true;
        d->source->setIndicator(indicator_);
    }
}

void InputHub::readSource(Device& d, double now, std::vector<model::Action>& out) {
    records_.clear();
    std::string why;
    const RawSource::ReadStatus status =
        d.source->read(now, limits_.recordsPerFrame, records_, why);
    for (const RawRecord& r : records_) {
        feed(d, r, out);
        if (!d.source) { // an Unplugged record among them
            return;
        }
    }
    if (status == RawSource::ReadStatus::Gone) {
        if (recordObserver_) {
            RawRecord gone;
            gone.kind = RawRecord::Kind::Unplugged;
            gone.time = now;
            gone.device = d.spec.name;
            recordObserver_(gone);
        }
        unplugged(d, now, why, out);
    } else if (status == RawSource::ReadStatus::Failed) {
        problem(d, now, d.spec.name + ": " + why);
    }
}

void InputHub::poll(double now, std::vector<model::Action>& out) {
    if (live_) {
        if (backend_.devicesChanged && backend_.devicesChanged(now)) {
            for (auto& d : devices_) {
                d->nextOpen = std::min(d->nextOpen, now);
            }
        }
        openDue(now);
        for (auto& d : devices_) {
            if (d->source) {
                readSource(*d, now, out);
            }
        }
    }
    while (!pending_.empty() && pending_.front().time + replayOffset_ <= now) {
        RawRecord r = std::move(pending_.front());
        pending_.pop_front();
        r.time += replayOffset_;
        inject(r, out);
    }
    for (auto& d : devices_) {
        if (d->decoder) {
            d->decoder->tick(now, events_);
            deliver(events_, out);
        }
        takeProblems(*d, now);
    }
    bindings_.tick(now, out);
}

void InputHub::setIndicator(Indicator indicator) {
    if (indicator == indicator_) {
        return;
    }
    indicator_ = indicator;
    for (auto& d : devices_) {
        if (d->source) {
            d->source->setIndicator(indicator);
        }
    }
}

std::vector<workflow::DeviceLink> InputHub::links() const {
    std::vector<workflow::DeviceLink> out;
    out.reserve(devices_.size());
    for (const auto& d : devices_) {
        out.push_back({d->spec.name, kindName(d->spec.kind), d->connected});
    }
    return out;
}

bool InputHub::busy() const {
    return !pending_.empty() || bindings_.repeating();
}

} // namespace steerseg::input
