#pragma once

// The little of a GPIO chip the sources need, so the libgpiod 1.6 implementation
// (gpio_chip_v1.cpp, Debian 12) can be replaced by a 2.x one without touching gpio_source.cpp.
// Every failure returns nothing (or false) and a one-line `problem` naming the chip and line.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace steerseg::platform::input::gpio {

struct GpioEdge {
    bool active = false; // the line's new logical level (active-low applied)
    double time = 0.0;   // kernel timestamp, seconds on CLOCK_MONOTONIC
};

class GpioInputLine {
  public:
    enum class Status { Ok, Gone, Failed };
    virtual ~GpioInputLine() = default;
    [[nodiscard]] virtual int fd() const = 0; // readable when edges are pending
    // The current logical level; false on error.
    [[nodiscard]] virtual bool level() const = 0;
    // Appends at most `maxEdges` pending edges without blocking.
    virtual Status readEdges(std::size_t maxEdges, std::vector<GpioEdge>& out,
                             std::string& problem) = 0;
};

class GpioOutputLine {
  public:
    virtual ~GpioOutputLine() = default;
    // Sets the logical level; false and `problem` (errno in `error`) when the chip refuses.
    virtual bool set(bool active, int& error, std::string& problem) = 0;
};

class GpioChip {
  public:
    virtual ~GpioChip() = default;
    [[nodiscard]] virtual const std::string& node() const = 0;
    // `line` is a line name or an offset in digits; the consumer is "steerseg".
    virtual std::unique_ptr<GpioInputLine> requestBothEdges(const std::string& line, bool activeLow,
                                                            std::string& problem) = 0;
    virtual std::unique_ptr<GpioOutputLine> requestOutput(const std::string& line, bool activeLow,
                                                          bool initial, std::string& problem) = 0;
};

struct GpioChipInfo {
    std::string node;  // "/dev/gpiochip0"
    std::string label; // the driver's label
    unsigned lines = 0;
};

// `chip` is a node path, a name ("gpiochip0"), a number ("0") or a label; searched in `devDir`.
std::unique_ptr<GpioChip> openGpioChipV1(const std::string& chip, std::string& problem,
                                         const std::string& devDir = "/dev");
std::vector<GpioChipInfo> listGpioChipsV1(const std::string& devDir = "/dev");

} // namespace steerseg::platform::input::gpio
