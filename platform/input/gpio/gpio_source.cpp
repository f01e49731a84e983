// GPIO sources over gpio_chip.hpp: an input line yields GpioEdge records stamped with the
// kernel's edge time (the decoder debounces on them, so bounces a few ms apart stay apart even
// when one frame reads them together); an output line is a status LED.
#include "platform/input/gpio/gpio_chip.hpp"
#include "platform/input/sources.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <ctime>

namespace steerseg::platform::input {
namespace {

double clockSeconds(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// Kernels before 5.7 stamp v1 line events with CLOCK_REALTIME, later ones CLOCK_MONOTONIC:
// the edge is placed on the caller's clock by its age on whichever clock it is close to.
double edgeTime(double kernelTime, double now) {
    const double monotonic = clockSeconds(CLOCK_MONOTONIC);
    double age = monotonic - kernelTime;
    if (std::abs(age) > 3600.0) {
        age = clockSeconds(CLOCK_REALTIME) - kernelTime;
    }
    return now - std::clamp(age, 0.0, 3600.0);
}

class GpioInputSource final : public RawSource {
  public:
    GpioInputSource(std::string name, std::unique_ptr<gpio::GpioChip> chip,
                    std::unique_ptr<gpio::GpioInputLine> line)
        : name_(std::move(name)), chip_(std::move(chip)), line_(std::move(line)) {}

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] int fd() const override { return line_->fd(); }

    ReadStatus read(double now, std::size_t maxRecords, std::vector<RawRecord>& out,
                    std::string& problem) override {
        if (!started_ && maxRecords > 0) {
            started_ = true;
            // A pedal already held when the line is opened produces no edge: say so once.
            if (line_->level()) {
                out.push_back(record(now, true));
                --maxRecords;
            }
        }
        edges_.clear();
        const auto status = line_->readEdges(maxRecords, edges_, problem);
        for (const gpio::GpioEdge& edge : edges_) {
            out.push_back(record(edgeTime(edge.time, now), edge.active));
        }
        switch (status) {
        case gpio::GpioInputLine::Status::Ok:
            return ReadStatus::Ok;
        case gpio::GpioInputLine::Status::Gone:
            return ReadStatus::Gone;
        case gpio::GpioInputLine::Status::Failed:
            break;
        }
        return ReadStatus::Failed;
    }

  private:
    RawRecord record(double time, bool active) const {
        RawRecord r;
        r.kind = RawRecord::Kind::GpioEdge;
        r.time = time;
        r.device = name_;
        r.active = active;
        return r;
    }
    std::string name_;
    std::unique_ptr<gpio::GpioChip> chip_;
    std::unique_ptr<gpio::GpioInputLine> line_;
    std::vector<gpio::GpioEdge> edges_;
    bool started_ = false;
};

// Pulsing has no thread of its own: each read() sets the level the ~1 Hz blink has reached.
class GpioLedSource final : public RawSource {
  public:
    GpioLedSource(std::string name, std::unique_ptr<gpio::GpioChip> chip,
                  std::unique_ptr<gpio::GpioOutputLine> line)
        : name_(std::move(name)), chip_(std::move(chip)), line_(std::move(line)) {}

    [[nodiscard]] const std::string& name() const override { return name_; }
    [[nodiscard]] int fd() const override { return -1; }

    ReadStatus read(double now, std::size_t, std::vector<RawRecord>&,
                    std::string& problem) override {
        bool want = false;
        switch (indicator_) {
        case Indicator::Off:
            break;
        case Indicator::Steady:
            want = true;
            break;
        case Indicator::Pulsing:
            want = std::fmod(std::max(now, 0.0), kBlinkPeriod) < kBlinkPeriod / 2.0;
            break;
        }
        if (want == level_) {
            return ReadStatus::Ok;
        }
        int error = 0;
        if (!line_->set(want, error, problem)) {
            return error == ENODEV || error == ENXIO ? ReadStatus::Gone : ReadStatus::Failed;
        }
        level_ = want;
        return ReadStatus::Ok;
    }

    void setIndicator(Indicator indicator) override { indicator_ = indicator; }

  private:
    static constexpr double kBlinkPeriod = 1.0;
    std::string name_;
    std::unique_ptr<gpio::GpioChip> chip_;
    std::unique_ptr<gpio::GpioOutputLine> line_;
    Indicator indicator_ = Indicator::Off;
    bool level_ = false; // the line is requested low
};

} // namespace

std::unique_ptr<RawSource> openGpioSource(const DeviceSpec& spec, std::string& problem) {
    problem.clear();
    if (spec.kind != DeviceSpec::Kind::GpioInput && spec.kind != DeviceSpec::Kind::GpioLed) {
        problem = spec.name + ": not a GPIO device";
        return nullptr;
    }
    if (spec.line.empty()) {
        problem = spec.name + ": no GPIO line given";
        return nullptr;
    }
    std::string why;
    auto chip = gpio::openGpioChipV1(spec.chip, why);
    if (!chip) {
        problem = spec.name + ": " + why;
        return nullptr;
    }
    if (spec.kind == DeviceSpec::Kind::GpioInput) {
        auto line = chip->requestBothEdges(spec.line, spec.activeLow, why);
        if (!line) {
            problem = spec.name + ": " + why;
            return nullptr;
        }
        return std::make_unique<GpioInputSource>(spec.name, std::move(chip), std::move(line));
    }
    auto line = chip->requestOutput(spec.line, spec.activeLow, false, why);
    if (!line) {
        problem = spec.name + ": " + why;
        return nullptr;
    }
    return std::make_unique<GpioLedSource>(spec.name, std::move(chip), std::move(line));
}

std::vector<AttachedDevice> listGpioChips() {
    std::vector<AttachedDevice> devices;
    for (const gpio::GpioChipInfo& info : gpio::listGpioChipsV1()) {
        AttachedDevice device;
        device.kind = "gpiochip";
        device.node = info.node;
        device.description = info.label + " (" + std::to_string(info.lines) + " lines)";
        devices.push_back(std::move(device));
    }
    return devices;
}

} // namespace steerseg::platform::input
