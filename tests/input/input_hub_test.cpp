// The kiosk's input hub on recordings (tests/data/input/) through the real decoders, and on a
// scripted live source: unplug in the middle of a turn releases and stops, replug resumes, a
// flood is capped, garbage is logged (rate-limited) and skipped.
#include "config/kiosk_config.hpp"
#include "input/input_backend.hpp"
#include "input/input_hub.hpp"
#include "platform/input/recording.hpp"

#include <chrono>
#include <deque>
#include <gtest/gtest.h>
#include <sstream>
#include <variant>

namespace steerseg::test {
namespace {

using input::InputHub;
using model::Action;
using platform::input::RawRecord;
using platform::input::RawSource;

const std::string kData = STEERSEG_INPUT_DATA_DIR;

InputHub makeHub(std::ostream& log, InputHub::Backend backend = input::replayInputBackend(),
                 bool live = false, input::InputHubLimits limits = {}) {
    const config::KioskConfig c = config::defaultConfig();
    return InputHub(input::deviceSpecs(c.input.devices),
                    input::ControlBindings(c.bindings.knobs, c.bindings.buttons),
                    std::move(backend), live, log, limits);
}

template <typename A> int count(const std::vector<Action>& actions) {
    return static_cast<int>(std::count_if(actions.begin(), actions.end(), [](const Action& a) {
        return std::holds_alternative<A>(a);
    }));
}

double nudged(const std::vector<Action>& actions) {
    double total = 0.0;
    for (const Action& a : actions) {
        if (const auto* n = std::get_if<model::NudgeSelected>(&a)) {
            total += n->steps;
        }
    }
    return total;
}

bool connected(const InputHub& hub, const std::string& name) {
    for (const workflow::DeviceLink& l : hub.links()) {
        if (l.name == name) {
            return l.connected;
        }
    }
    ADD_FAILURE() << "no device " << name;
    return false;
}

int lines(const std::string& text, const std::string& part) {
    int n = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        n += line.find(part) != std::string::npos ? 1 : 0;
    }
    return n;
}

// Polls at 100 Hz from `from` to `to` (the recording's clock), returning the actions.
std::vector<Action> run(InputHub& hub, double from, double to) {
    std::vector<Action> out;
    for (int i = 0; from + i * 0.01 <= to + 1e-9; ++i) {
        hub.poll(from + i * 0.01, out);
    }
    return out;
}

TEST(InputHub, UnplugInTheMiddleOfATurnReleasesAndStopsReplugResumes) {
    std::ostringstream log;
    InputHub hub = makeHub(log);
    const platform::input::Recording rec =
        platform::input::readRecording(kData + "/hub_unplug_mid_turn.rec");
    ASSERT_TRUE(rec.problems.empty()) << rec.problems.front();
    hub.replay(rec.records, 0.0);

    const std::vector<Action> held = run(hub, 0.0, 0.99);
    EXPECT_EQ(count<model::Run>(held), 1) << "the pedal, once debounced";
    EXPECT_EQ(count<model::Pause>(held), 0);
    // The ring at +4/7 from 0.2 s: one nudge at once, then 20 * 4/7 a second for 0.79 s.
    EXPECT_NEAR(nudged(held), 10.0 * (1 + 20.0 * 4 / 7 * 0.79), 10.0 * 1);
    EXPECT_TRUE(connected(hub, "shuttle"));
    EXPECT_TRUE(connected(hub, "pedal"));

    const std::vector<Action> gone = run(hub, 1.0, 1.99);
    EXPECT_EQ(count<model::Pause>(gone), 1) << "the held pedal is released: it stops";
    EXPECT_EQ(count<model::Run>(gone), 0);
    EXPECT_EQ(nudged(gone), 0.0) << "the ring is at rest: no more nudges";
    EXPECT_FALSE(connected(hub, "shuttle"));
    EXPECT_FALSE(connected(hub, "pedal"));
    EXPECT_EQ(lines(log.str(), "shuttle: disconnected"), 1) << log.str();

    const std::vector<Action> back = run(hub, 2.0, 3.0);
    EXPECT_TRUE(connected(hub, "shuttle"));
    EXPECT_EQ(nudged(back), 2.0) << "the jog after the replug, counted from its new counter";
    EXPECT_FALSE(hub.busy());
}

TEST(InputHub, GarbageIsLoggedRateLimitedAndSkipped) {
    std::ostringstream log;
    InputHub hub = makeHub(log);
    const platform::input::Recording rec =
        platform::input::readRecording(kData + "/hub_garbage.rec");
    ASSERT_TRUE(rec.problems.empty()) << rec.problems.front();
    hub.replay(rec.records, 0.0);
    const std::vector<Action> out = run(hub, 0.0, 2.0);
    EXPECT_EQ(nudged(out), 4.0) << "every good report, none of the bad";
    // Five problems in the first second: one line, then one with the count of the rest.
    EXPECT_EQ(lines(log.str(), "input: shuttle"), 2) << log.str();
    EXPECT_EQ(lines(log.str(), "(and 4 more since the last line)"), 1) << log.str();
}

TEST(InputHub, RecordsOfNoConfiguredDeviceAreSkippedWithOneLine) {
    std::ostringstream log;
    InputHub hub = makeHub(log);
    std::vector<Action> out;
    for (int i = 0; i < 100; ++i) {
        RawRecord r;
        r.kind = RawRecord::Kind::GpioEdge;
        r.time = 0.001 * i;
        r.device = "trackball";
        r.active = (i % 2) == 0;
        hub.inject(r, out);
    }
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(lines(log.str(), "no configured device \"trackball\""), 1) << log.str();
}

TEST(InputHub, AReplayedFloodIsCapped) {
    std::ostringstream log;
    input::InputHubLimits limits;
    limits.recordsPerSecond = 1000;
    InputHub hub = makeHub(log, input::replayInputBackend(), false, limits);
    // 20000 PowerMate detents in one second (each with its SYN_REPORT).
    std::vector<RawRecord> flood;
    for (int i = 0; i < 20000; ++i) {
        for (const auto& [type, code, value] : {std::tuple{2, 7, 1}, std::tuple{0, 0, 0}}) {
            RawRecord r;
            r.kind = RawRecord::Kind::Evdev;
            r.time = i * 5e-5;
            r.device = "powermate";
            r.type = static_cast<std::uint16_t>(type);
            r.code = static_cast<std::uint16_t>(code);
            r.value = value;
            flood.push_back(r);
        }
    }
    hub.replay(std::move(flood), 0.0);
    const std::vector<Action> out = run(hub, 0.0, 1.5);
    const int turns = count<model::NudgeParam>(out);
    EXPECT_GT(turns, 0);
    EXPECT_LE(turns, 500) << "1000 records a second are 500 detents with their SYNs";
    EXPECT_EQ(lines(log.str(), "flooding"), 1) << log.str();
}

// A live source the test scripts: records to hand out each read, then Gone.
class ScriptedSource final : public RawSource {
  public:
    struct Shared {
        std::deque<RawRecord> pending;
        bool gone = false;
        bool endless = false; // a flood: every read is full
        int reads = 0;
        std::vector<platform::input::Indicator> indicators;
    };
    ScriptedSource(std::string name, Shared& shared) : name_(std::move(name)), s_(shared) {}
    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] int fd() const override { return -1; }
    ReadStatus read(double now, std::size_t maxRecords, std::vector<RawRecord>& out,
                    std::string& problem) override {
        ++s_.reads;
        if (s_.endless) {
            for (std::size_t i = 0; i < maxRecords; ++i) {
                RawRecord r;
                r.kind = RawRecord::Kind::Evdev;
                r.time = now;
                r.device = name_;
                r.type = (i % 2) == 0 ? 2 : 0;
                r.code = (i % 2) == 0 ? 7 : 0;
                r.value = (i % 2) == 0 ? 1 : 0;
                out.push_back(r);
            }
            return ReadStatus::Ok;
        }
        for (std::size_t i = 0; i < maxRecords && !s_.pending.empty(); ++i) {
            RawRecord r = s_.pending.front();
            s_.pending.pop_front();
            r.time = now;
            out.push_back(r);
        }
        if (s_.gone) {
            problem = "device removed";
            return ReadStatus::Gone;
        }
        return ReadStatus::Ok;
    }
    void setIndicator(platform::input::Indicator i) override { s_.indicators.push_back(i); }

  private:
    std::string name_;
    Shared& s_;
};

TEST(InputHub, LiveDeviceRetriedUntilPresentThenGoneThenBack) {
    ScriptedSource::Shared shared;
    bool present = false;
    int opens = 0;
    InputHub::Backend backend = input::replayInputBackend();
    backend.open = [&](const platform::input::DeviceSpec& spec,
                       std::string& problem) -> std::unique_ptr<RawSource> {
        if (spec.name != "powermate") {
            problem = spec.name + ": not here";
            return nullptr;
        }
        ++opens;
        if (!present) {
            problem = "powermate: no evdev device 077d:0410 in /dev/input";
            return nullptr;
        }
        return std::make_unique<ScriptedSource>("powermate", shared);
    };
    std::ostringstream log;
    InputHub hub = makeHub(log, backend, true);
    hub.setIndicator(platform::input::Indicator::Steady);
    std::vector<Action> out;
    hub.poll(0.0, out);
    hub.poll(1.0, out);
    hub.poll(2.5, out); // the retry: still missing
    EXPECT_EQ(opens, 2);
    EXPECT_EQ(lines(log.str(), "no evdev device"), 1) << "a lasting problem is logged once";
    present = true;
    hub.poll(5.0, out);
    EXPECT_TRUE(connected(hub, "powermate"));
    ASSERT_EQ(shared.indicators.size(), 1U) << "the LED is set when the device opens";
    EXPECT_EQ(shared.indicators[0], platform::input::Indicator::Steady);

    // Pressed, then pulled: the press is released (nothing bound to it, but no stuck state),
    // the device is shown disconnected and opened again at the next retry.
    for (const auto& [type, code, value] :
         {std::tuple{2, 7, 1}, std::tuple{0, 0, 0}, std::tuple{1, 256, 1}, std::tuple{0, 0, 0}}) {
        RawRecord r;
        r.kind = RawRecord::Kind::Evdev;
        r.device = "powermate";
        r.type = static_cast<std::uint16_t>(type);
        r.code = static_cast<std::uint16_t>(code);
        r.value = value;
        shared.pending.push_back(r);
    }
    out.clear();
    hub.poll(5.1, out);
    EXPECT_EQ(count<model::NudgeParam>(out), 1);
    EXPECT_EQ(count<model::ToggleRun>(out), 1);
    shared.gone = true;
    hub.poll(5.2, out);
    EXPECT_FALSE(connected(hub, "powermate"));
    EXPECT_EQ(lines(log.str(), "powermate: disconnected: device removed"), 1) << log.str();
    shared.gone = false;
    hub.poll(6.0, out); // before the retry
    EXPECT_FALSE(connected(hub, "powermate"));
    hub.poll(7.3, out);
    EXPECT_TRUE(connected(hub, "powermate"));
    EXPECT_EQ(lines(log.str(), "powermate: reconnected"), 1) << log.str();
}

TEST(InputHub, HotplugOpensAtOnce) {
    bool present = false;
    bool changed = false;
    ScriptedSource::Shared shared;
    InputHub::Backend backend = input::replayInputBackend();
    backend.open = [&](const platform::input::DeviceSpec& spec,
                       std::string& problem) -> std::unique_ptr<RawSource> {
        if (spec.name != "powermate" || !present) {
            problem = spec.name + ": not here";
            return nullptr;
        }
        return std::make_unique<ScriptedSource>("powermate", shared);
    };
    backend.devicesChanged = [&](double) { return std::exchange(changed, false); };
    std::ostringstream log;
    InputHub hub = makeHub(log, backend, true);
    std::vector<Action> out;
    hub.poll(0.0, out);
    present = true;
    hub.poll(0.1, out);
    EXPECT_FALSE(connected(hub, "powermate")) << "the retry is not due yet";
    changed = true;
    hub.poll(0.2, out);
    EXPECT_TRUE(connected(hub, "powermate"));
}

TEST(InputHub, ALiveFloodNeverStallsAFrame) {
    ScriptedSource::Shared shared;
    shared.endless = true;
    InputHub::Backend backend = input::replayInputBackend();
    backend.open = [&](const platform::input::DeviceSpec& spec,
                       std::string& problem) -> std::unique_ptr<RawSource> {
        if (spec.name != "powermate") {
            problem = "absent";
            return nullptr;
        }
        return std::make_unique<ScriptedSource>("powermate", shared);
    };
    std::ostringstream log;
    InputHub hub = makeHub(log, backend, true);
    std::vector<Action> out;
    double slowest = 0.0;
    for (int frame = 0; frame < 300; ++frame) { // ten seconds at 30 Hz
        const auto t0 = std::chrono::steady_clock::now();
        hub.poll(frame / 30.0, out);
        slowest = std::max(
            slowest, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    EXPECT_LT(slowest, 0.02) << "one frame's share of a flood is bounded";
    // 256 records a frame at 30 Hz is 7680 a second, capped at 2000: 1000 detents a second.
    EXPECT_LE(count<model::NudgeParam>(out), 10 * 1000 + 1000);
    EXPECT_LE(lines(log.str(), "input: powermate"), 12) << "one line a second at most";
    EXPECT_GE(lines(log.str(), "flooding"), 1);
}

TEST(InputHub, IndicatorFollowsTheWorkflow) {
    EXPECT_EQ(input::indicatorFor(model::State::Evolving), platform::input::Indicator::Steady);
    EXPECT_EQ(input::indicatorFor(model::State::Paused), platform::input::Indicator::Pulsing);
    EXPECT_EQ(input::indicatorFor(model::State::Inspect), platform::input::Indicator::Off);
    EXPECT_EQ(input::indicatorFor(model::State::NoScan), platform::input::Indicator::Off);
}

TEST(InputHub, SpecsFromTheConfig) {
    const auto specs = input::deviceSpecs(config::defaultConfig().input.devices);
    ASSERT_EQ(specs.size(), 6U);
    EXPECT_EQ(specs[0].kind, platform::input::DeviceSpec::Kind::Shuttle);
    EXPECT_EQ(specs[0].vendorId, 0x0b33);
    EXPECT_EQ(specs[0].productId, 0x0020);
    EXPECT_EQ(specs[3].usagePage, 0x01);
    EXPECT_EQ(specs[3].usage, 0x0e);
    EXPECT_EQ(specs[4].line, "PEDAL");
    EXPECT_TRUE(specs[4].activeLow);
    EXPECT_DOUBLE_EQ(specs[4].debounceSeconds, 0.02);
}

} // namespace
} // namespace steerseg::test
