#pragma once

// A HID report descriptor parsed into the input fields a decoder reads (HID 1.11, section 6.2.2):
// items, the global state with push/pop, local usages and usage ranges, report ids, and each
// input field's place in its report. Output and feature items are skipped (they do not move the
// input fields). Parsing is bounded: a descriptor over 4096 bytes, or with absurd sizes, counts
// or nesting, is refused with one line, never a crash.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace steerseg::platform::input::hid {

inline constexpr std::size_t kMaxDescriptorBytes = 4096;

struct HidCollection {
    std::uint16_t usagePage = 0;
    std::uint16_t usage = 0;
    std::uint8_t type = 0; // 0 physical, 1 application, 2 logical, ...
    int parent = -1;       // index into ReportDescriptor::collections, -1 at the top
};

// One value of an input report: a Report Count of N gives N fields.
struct HidField {
    std::uint8_t reportId = 0;   // 0 when the descriptor declares no report ids
    std::uint32_t bitOffset = 0; // from the first data byte (after the report id byte)
    std::uint32_t bitSize = 0;
    std::uint16_t usagePage = 0;
    std::uint16_t usage = 0; // for an array field, its first usage
    std::int64_t logicalMin = 0;
    std::int64_t logicalMax = 0;
    bool isSigned = false; // the logical minimum is negative: values are two's complement
    bool constant = false; // padding
    bool variable = false; // one value per usage (else an array of usage indices)
    bool relative = false;
    int collection = -1; // the innermost enclosing collection
};

struct ReportDescriptor {
    bool usesReportIds = false;
    std::vector<HidCollection> collections;
    std::vector<HidField> inputs;
    // Input report sizes in bits (data only), by report id (index 0 when no ids are used).
    std::vector<std::uint32_t> inputBits = std::vector<std::uint32_t>(256, 0);

    // The length hidapi returns for an input report of this id: the data bytes plus the id
    // byte where ids are used; 0 for an id the descriptor has no input fields for.
    [[nodiscard]] std::size_t inputReportBytes(std::uint8_t reportId) const;
    // Whether `field` lies within collection `ancestor` (at any depth).
    [[nodiscard]] bool within(const HidField& field, int ancestor) const;
};

// Nothing and a one-line `problem` for a descriptor it refuses.
std::optional<ReportDescriptor> parseReportDescriptor(std::span<const std::uint8_t> bytes,
                                                      std::string& problem);

} // namespace steerseg::platform::input::hid
