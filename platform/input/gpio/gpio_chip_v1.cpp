// gpio_chip.hpp through libgpiod 1.6's line API (the kernel's v1 character-device uAPI).
#include "platform/input/gpio/gpio_chip.hpp"
#include "platform/input/node_access.hpp"

#include <array>
#include <cerrno>
#include <cstring>
#include <gpiod.h>

namespace steerseg::platform::input::gpio {
namespace {

constexpr const char* kConsumer = "steerseg";

bool allDigits(const std::string& text) {
    return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
}

struct ChipCloser {
    void operator()(gpiod_chip* chip) const { gpiod_chip_close(chip); }
};
using ChipHandle = std::unique_ptr<gpiod_chip, ChipCloser>;

// The chip and line stay open together: a line is only valid while its chip is.
class V1InputLine final : public GpioInputLine {
  public:
    V1InputLine(std::shared_ptr<gpiod_chip> chip, gpiod_line* line, std::string label)
        : chip_(std::move(chip)), line_(line), label_(std::move(label)) {}
    ~V1InputLine() override { gpiod_line_release(line_); }
    V1InputLine(const V1InputLine&) = delete;
    V1InputLine& operator=(const V1InputLine&) = delete;

    [[nodiscard]] int fd() const override { return gpiod_line_event_get_fd(line_); }
    [[nodiscard]] bool level() const override { return gpiod_line_get_value(line_) == 1; }

    Status readEdges(std::size_t maxEdges, std::vector<GpioEdge>& out,
                     std::string& problem) override {
        std::array<gpiod_line_event, 16> events{};
        while (maxEdges > 0) {
            // gpiod_line_event_read_multiple blocks on an empty queue: ask poll() first.
            const timespec zero{0, 0};
            const int ready = gpiod_line_event_wait(line_, &zero);
            if (ready == 0) {
                return Status::Ok;
            }
            if (ready < 0) {
                return fail("waiting for edges", problem);
            }
            const auto want = static_cast<unsigned>(std::min(maxEdges, events.size()));
            const int got = gpiod_line_event_read_multiple(line_, events.data(), want);
            if (got < 0) {
                return fail("reading edges", problem);
            }
            for (int i = 0; i < got; ++i) {
                const gpiod_line_event& ev = events[static_cast<std::size_t>(i)];
                GpioEdge edge;
                edge.active = ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE;
                edge.time =
                    static_cast<double>(ev.ts.tv_sec) + static_cast<double>(ev.ts.tv_nsec) * 1e-9;
                out.push_back(edge);
            }
            maxEdges -= static_cast<std::size_t>(got);
        }
        return Status::Ok;
    }

  private:
    Status fail(const char* what, std::string& problem) const {
        const int err = errno;
        problem = label_ + ": " + what + " failed: " + std::strerror(err);
        return err == ENODEV || err == ENXIO ? Status::Gone : Status::Failed;
    }
    std::shared_ptr<gpiod_chip> chip_;
    gpiod_line* line_;
    std::string label_;
};

class V1OutputLine final : public GpioOutputLine {
  public:
    V1OutputLine(std::shared_ptr<gpiod_chip> chip, gpiod_line* line, std::string label)
        : chip_(std::move(chip)), line_(line), label_(std::move(label)) {}
    ~V1OutputLine() override { gpiod_line_release(line_); }
    V1OutputLine(const V1OutputLine&) = delete;
    V1OutputLine& operator=(const V1OutputLine&) = delete;

    bool set(bool active, int& error, std::string& problem) override {
        if (gpiod_line_set_value(line_, active ? 1 : 0) == 0) {
            return true;
        }
        error = errno;
        problem = label_ + ": setting the level failed: " + std::strerror(error);
        return false;
    }

  private:
    std::shared_ptr<gpiod_chip> chip_;
    gpiod_line* line_;
    std::string label_;
};

class V1Chip final : public GpioChip {
  public:
    V1Chip(ChipHandle chip, std::string node)
        : chip_(chip.release(), ChipCloser{}), node_(std::move(node)) {}
    [[nodiscard]] const std::string& node() const override { return node_; }

    std::unique_ptr<GpioInputLine> requestBothEdges(const std::string& line, bool activeLow,
                                                    std::string& problem) override {
        std::string label;
        gpiod_line* handle = find(line, label, problem);
        if (handle == nullptr) {
            return nullptr;
        }
        if (gpiod_line_request_both_edges_events_flags(handle, kConsumer, flags(activeLow)) != 0) {
            problem = requestProblem(handle, label);
            return nullptr;
        }
        return std::make_unique<V1InputLine>(chip_, handle, label);
    }

    std::unique_ptr<GpioOutputLine> requestOutput(const std::string& line, bool activeLow,
                                                  bool initial, std::string& problem) override {
        std::string label;
        gpiod_line* handle = find(line, label, problem);
        if (handle == nullptr) {
            return nullptr;
        }
        if (gpiod_line_request_output_flags(handle, kConsumer, flags(activeLow), initial ? 1 : 0) !=
            0) {
            problem = requestProblem(handle, label);
            return nullptr;
        }
        return std::make_unique<V1OutputLine>(chip_, handle, label);
    }

  private:
    static int flags(bool activeLow) { return activeLow ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW : 0; }

    gpiod_line* find(const std::string& line, std::string& label, std::string& problem) {
        label = node_ + " line '" + line + "'";
        gpiod_line* handle = nullptr;
        if (allDigits(line)) {
            const unsigned offset = line.size() > 6 ? ~0U : static_cast<unsigned>(std::stoul(line));
            if (offset >= gpiod_chip_num_lines(chip_.get())) {
                problem = label + ": the chip has " +
                          std::to_string(gpiod_chip_num_lines(chip_.get())) + " lines";
                return nullptr;
            }
            handle = gpiod_chip_get_line(chip_.get(), offset);
        } else {
            handle = gpiod_chip_find_line(chip_.get(), line.c_str());
        }
        if (handle == nullptr) {
            problem = label + ": " +
                      (errno == ENOENT ? std::string("no line of that name")
                                       : std::string("lookup failed: ") + std::strerror(errno));
        }
        return handle;
    }

    static std::string requestProblem(gpiod_line* line, const std::string& label) {
        const int err = errno;
        if (err == EBUSY) {
            const char* owner = gpiod_line_consumer(line);
            return label + ": in use by '" + (owner != nullptr ? owner : "another program") + "'";
        }
        return label + ": request failed: " + std::strerror(err);
    }

    std::shared_ptr<gpiod_chip> chip_;
    std::string node_;
};

ChipHandle openPath(const std::string& node, std::string& problem) {
    ChipHandle chip(gpiod_chip_open(node.c_str()));
    if (!chip) {
        problem = nodeOpenProblem(node, "open", errno);
    }
    return chip;
}

} // namespace

std::unique_ptr<GpioChip> openGpioChipV1(const std::string& chip, std::string& problem,
                                         const std::string& devDir) {
    problem.clear();
    if (chip.empty()) {
        problem = "gpio: no chip given";
        return nullptr;
    }
    std::string node;
    if (chip.front() == '/') {
        node = chip;
    } else if (chip.rfind("gpiochip", 0) == 0) {
        node = devDir + "/" + chip;
    } else if (allDigits(chip)) {
        node = devDir + "/gpiochip" + chip;
    }
    if (!node.empty()) {
        ChipHandle handle = openPath(node, problem);
        return handle ? std::make_unique<V1Chip>(std::move(handle), node) : nullptr;
    }
    // A label: open each chip and compare.
    for (const std::string& candidate : listNodes(devDir, "gpiochip")) {
        std::string ignored;
        ChipHandle handle = openPath(candidate, ignored);
        if (handle && chip == gpiod_chip_label(handle.get())) {
            return std::make_unique<V1Chip>(std::move(handle), candidate);
        }
    }
    problem = "gpio chip '" + chip + "': no chip with that label in " + devDir;
    return nullptr;
}

std::vector<GpioChipInfo> listGpioChipsV1(const std::string& devDir) {
    std::vector<GpioChipInfo> chips;
    for (const std::string& node : listNodes(devDir, "gpiochip")) {
        GpioChipInfo info;
        info.node = node;
        std::string problem;
        ChipHandle handle = openPath(node, problem);
        if (handle) {
            info.label = gpiod_chip_label(handle.get());
            info.lines = gpiod_chip_num_lines(handle.get());
        } else {
            info.label = "(" + problem + ")";
        }
        chips.push_back(std::move(info));
    }
    return chips;
}

} // namespace steerseg::platform::input::gpio
