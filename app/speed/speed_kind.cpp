#include "speed/speed_kind.hpp"

#include <array>
#include <utility>

namespace steerseg::speed {

namespace {
constexpr std::array<std::pair<SpeedKind, const char*>, 3> kNames{{
    {SpeedKind::Threshold, "threshold"},
    {SpeedKind::Edge, "edge"},
    {SpeedKind::Classify, "classify"},
}};
} // namespace

const char* speedKindName(SpeedKind kind) {
    for (const auto& [k, name] : kNames) {
        if (k == kind) {
            return name;
        }
    }
    return "threshold";
}

std::optional<SpeedKind> parseSpeedKind(std::string_view name) {
    for (const auto& [k, n] : kNames) {
        if (name == n) {
            return k;
        }
    }
    return std::nullopt;
}

} // namespace steerseg::speed
