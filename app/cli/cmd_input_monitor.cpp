// `steerseg input-monitor`: what a field engineer runs to see why a knob does nothing. Lists the
// attached devices and the configured device each matches, prints the decoded control events
// and the actions they are bound to, records the raw streams, or replays a recording through
// the same decoders and bindings as the kiosk (docs/input-devices.md, "input-monitor").
// Read-only towards the devices (it does drive the LEDs' state: off), so it runs as any user;
// as root it simply sees every node.
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/kiosk_config_file.hpp"
#include "config/config_loader.hpp"
#include "files/file_append.hpp"
#include "files/file_error.hpp"
#include "files/file_write.hpp"
#include "input/input_backend.hpp"
#include "input/input_hub.hpp"
#include "platform/input/recording.hpp"
#include "platform/input/sources.hpp"
#include "scan/scan_reader.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <thread>
#include <variant>

namespace steerseg::cli {

namespace {

using platform::input::AttachedDevice;
using platform::input::ControlEvent;
using platform::input::DeviceSpec;

constexpr std::string_view kRecordingHeader = "# steerseg input recording 1\n";
constexpr double kFrameSeconds = 1.0 / 100.0; // the monitor's poll rate, live and replayed
constexpr double kReplayTail = 1.0;           // after a replay's last record: a held ring's repeats

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int /*signal*/) {
    g_interrupted = true;
}

std::string seconds(double t) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6f", t);
    return text;
}

std::string hex4(std::uint16_t v) {
    char text[8];
    std::snprintf(text, sizeof text, "%04x", static_cast<unsigned>(v));
    return text;
}

std::string describe(const ControlEvent& e) {
    std::ostringstream out;
    out << e.control << ' ';
    switch (e.kind) {
    case ControlEvent::Kind::Step:
        out << "step " << (e.steps > 0 ? "+" : "") << e.steps;
        break;
    case ControlEvent::Kind::Position:
        out << "position " << e.position;
        break;
    case ControlEvent::Kind::Press:
        out << "press";
        break;
    case ControlEvent::Kind::Release:
        out << "release";
        break;
    }
    return out.str();
}

// The action's name and, for the relative ones, how far: what the workflow will be asked.
std::string describe(const model::Action& a) {
    std::ostringstream out;
    out << model::actionName(a);
    if (const auto* n = std::get_if<model::NudgeSelected>(&a)) {
        out << ' ' << n->steps;
    } else if (const auto* p = std::get_if<model::NudgeParam>(&a)) {
        out << ' ' << model::paramName(p->param) << ' ' << p->steps;
    } else if (const auto* c = std::get_if<model::CycleParam>(&a)) {
        out << ' ' << c->delta;
    } else if (const auto* s = std::get_if<model::PageSlice>(&a)) {
        out << ' ' << model::sliceAxisName(s->axis) << ' ' << s->delta;
    } else if (const auto* r = std::get_if<model::RotateView>(&a)) {
        out << ' ' << r->yaw << ' ' << r->pitch;
    } else if (const auto* z = std::get_if<model::ZoomView>(&a)) {
        out << ' ' << z->factor;
    }
    return out.str();
}

std::string describe(const std::vector<model::Action>& actions, bool bound) {
    if (actions.empty()) {
        return bound ? "(no action)" : "(unbound)";
    }
    std::string out;
    for (const model::Action& a : actions) {
        out += (out.empty() ? "" : ", ") + describe(a);
    }
    return out;
}

// The configured devices an attached one would be opened as (the sources' own matching rules:
// ids and usage where non-zero, an evdev path, a GPIO chip by name or label).
std::string matches(const AttachedDevice& a, const std::vector<DeviceSpec>& specs) {
    std::string names;
    for (const DeviceSpec& s : specs) {
        bool match = false;
        const bool ids = (s.vendorId == 0 || s.vendorId == a.vendorId) &&
                         (s.productId == 0 || s.productId == a.productId);
        switch (s.kind) {
        case DeviceSpec::Kind::Shuttle:
        case DeviceSpec::Kind::Radial:
            match = a.kind == "hid" && ids && (s.usagePage == 0 || s.usagePage == a.usagePage) &&
                    (s.usage == 0 || s.usage == a.usage);
            break;
        case DeviceSpec::Kind::PowerMate:
            match = a.kind == "evdev" && (s.path.empty() ? ids : s.path == a.node);
            break;
        case DeviceSpec::Kind::GpioInput:
        case DeviceSpec::Kind::GpioLed:
            match = a.kind == "gpiochip" &&
                    (a.node == s.chip || a.node == "/dev/" + s.chip || a.description == s.chip);
            break;
        }
        if (match) {
            names += (names.empty() ? "" : ", ") + s.name;
        }
    }
    return names.empty() ? "(no configured device)" : "-> " + names;
}

void listAttached(const std::vector<DeviceSpec>& specs, std::ostream& out) {
    std::vector<AttachedDevice> all = platform::input::listHidDevices();
    for (auto list : {platform::input::listEvdevDevices(), platform::input::listGpioChips()}) {
        all.insert(all.end(), list.begin(), list.end());
    }
    out << "attached devices: " << all.size() << '\n';
    for (const AttachedDevice& a : all) {
        out << "  " << a.kind << ' ' << a.node;
        if (a.kind != "gpiochip") {
            out << ' ' << hex4(a.vendorId) << ':' << hex4(a.productId);
        }
        if (a.kind == "hid") {
            out << " usage " << hex4(a.usagePage) << ':' << hex4(a.usage);
        }
        out << " \"" << a.description << "\" " << matches(a, specs) << '\n';
    }
}

// Prints each event with its actions as it is decoded; ring repeats (actions without an event
// of their own) are printed after the poll that made them.
class Printer {
  public:
    explicit Printer(std::ostream& out) : out_(out) {}
    void attach(input::InputHub& hub) {
        hub.setObserver([this, &hub](const ControlEvent& e, const std::vector<model::Action>& a) {
            out_ << seconds(e.time) << ' ' << describe(e) << " -> "
                 << describe(a, hub.bindings().bound(e.control)) << '\n';
            observed_ += a.size();
        });
    }
    void poll(input::InputHub& hub, double now) {
        actions_.clear();
        observed_ = 0;
        hub.poll(now, actions_);
        for (std::size_t i = observed_; i < actions_.size(); ++i) {
            out_ << seconds(now) << " (repeat) -> " << describe(actions_[i]) << '\n';
        }
        out_.flush();
    }

  private:
    std::ostream& out_;
    std::vector<model::Action> actions_;
    std::size_t observed_ = 0;
};

int replay(const std::string& file, const config::KioskConfig& cfg) {
    platform::input::Recording recording = platform::input::readRecording(file);
    for (const std::string& p : recording.problems) {
        std::cout << "problem: " << p << '\n';
    }
    if (recording.records.empty()) {
        throw std::runtime_error(file + ": no records to replay");
    }
    std::cout << "replaying " << recording.records.size() << " records of " << file << '\n';
    input::InputHubLimits limits;
    input::InputHub hub(input::deviceSpecs(cfg.input.devices),
                        input::ControlBindings(cfg.bindings.knobs, cfg.bindings.buttons),
                        input::replayInputBackend(), false, std::cout, limits);
    Printer printer(std::cout);
    printer.attach(hub);
    // On the recording's own clock, in monitor frames: as fast as the machine goes.
    const double start = recording.records.front().time;
    const double end = recording.records.back().time + kReplayTail;
    hub.replay(std::move(recording.records), start);
    for (double now = start; now <= end + kFrameSeconds / 2; now += kFrameSeconds) {
        printer.poll(hub, now);
    }
    return kExitOk;
}

int live(const config::KioskConfig& cfg, std::optional<double> maxSeconds,
         const std::optional<std::string>& recordFile) {
    const std::vector<DeviceSpec> specs = input::deviceSpecs(cfg.input.devices);
    listAttached(specs, std::cout);
    // Appended record by record and synced, so a crash or a full disk keeps what came before.
    std::unique_ptr<files::AppendFile> record;
    if (recordFile) {
        files::writeFileAtomically(*recordFile, {std::as_bytes(std::span(kRecordingHeader))});
        record = std::make_unique<files::AppendFile>(*recordFile);
    }
    input::InputHubLimits limits;
    input::InputHub hub(specs, input::ControlBindings(cfg.bindings.knobs, cfg.bindings.buttons),
                        input::liveInputBackend(std::cout, ""), true, std::cout, limits);
    Printer printer(std::cout);
    printer.attach(hub);
    std::optional<files::WriteError> recordError;
    if (record) {
        hub.setRecordObserver([&record, &recordError](const platform::input::RawRecord& r) {
            if (recordError) {
                return;
            }
            try {
                record->append(platform::input::formatRecordLine(r) + '\n');
            } catch (const files::WriteError& e) {
                recordError = e; // the records before it are kept
            }
        });
    }
    std::cout << "watching " << specs.size() << " configured devices";
    if (maxSeconds) {
        std::cout << " for " << *maxSeconds << " s";
    }
    std::cout << " (Ctrl-C stops)\n";
    g_interrupted = false;
    void (*previous)(int) = std::signal(SIGINT, onInterrupt);
    const auto start = std::chrono::steady_clock::now();
    for (;;) {
        const double now =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (g_interrupted || (maxSeconds && now >= *maxSeconds)) {
            break;
        }
        printer.poll(hub, now);
        std::this_thread::sleep_for(std::chrono::duration<double>(kFrameSeconds));
    }
    std::signal(SIGINT, previous);
    if (recordError) {
        throw *recordError;
    }
    if (record) {
        std::cout << "recorded to " << *recordFile << '\n';
    }
    return kExitOk;
}

} // namespace

int runInputMonitor(std::span<const std::string> words) {
    const Args args(words, {"config", "seconds", "record", "replay"}, {});
    if (!args.positional().empty()) {
        throw UsageError("unexpected '" + args.positional().front() + "'");
    }
    const std::optional<double> maxSeconds = args.number("seconds");
    if (maxSeconds && !(*maxSeconds > 0.0)) {
        throw UsageError("--seconds: expected a positive number of seconds");
    }
    const auto replayFile = args.value("replay");
    if (replayFile && (args.value("record") || maxSeconds)) {
        throw UsageError("--replay takes neither --record nor --seconds");
    }
    const config::LoadedConfig loaded =
        readKioskConfig(args.value("config"), "input-monitor", std::cerr);
    if (replayFile) {
        return replay(*replayFile, loaded.config);
    }
    return live(loaded.config, maxSeconds, args.value("record"));
}

} // namespace steerseg::cli
