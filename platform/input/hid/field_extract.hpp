#pragma once

// Reads one field of a HID report: `bitSize` bits (1..32) starting `bitOffset` bits into
// `data`, least significant bit first (HID 1.11, section 5.8), sign-extended where signed.
#include <cstdint>
#include <optional>
#include <span>

namespace steerseg::platform::input::hid {

// Nothing when the field does not lie wholly within `data` or its size is not 1..32.
std::optional<std::int64_t> extractField(std::span<const std::uint8_t> data,
                                         std::uint32_t bitOffset, std::uint32_t bitSize,
                                         bool isSigned);

} // namespace steerseg::platform::input::hid
