#include "platform/input/hid/field_extract.hpp"

namespace steerseg::platform::input::hid {

std::optional<std::int64_t> extractField(std::span<const std::uint8_t> data,
                                         std::uint32_t bitOffset, std::uint32_t bitSize,
                                         bool isSigned) {
    if (bitSize == 0 || bitSize > 32) {
        return std::nullopt;
    }
    const std::uint64_t end = std::uint64_t{bitOffset} + bitSize;
    if (end > std::uint64_t{data.size()} * 8) {
        return std::nullopt;
    }
    std::uint64_t raw = 0;
    for (std::uint32_t i = 0; i < bitSize; ++i) {
        const std::uint64_t bit = std::uint64_t{bitOffset} + i;
        const unsigned byte = data[static_cast<std::size_t>(bit / 8)];
        raw |= std::uint64_t{(byte >> (bit % 8)) & 1U} << i;
    }
    if (isSigned && (raw >> (bitSize - 1)) != 0) {
        return static_cast<std::int64_t>(raw) - (std::int64_t{1} << bitSize);
    }
    return static_cast<std::int64_t>(raw);
}

} // namespace steerseg::platform::input::hid
