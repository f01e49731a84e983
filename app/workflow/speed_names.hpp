#pragma once

// The speed kinds' names for the workflow, config and scripts, header-only: speed_kind.cpp
// lives in steerseg_speed, which links GL code the workflow and config must not link. The
// names must stay speed::speedKindName's (the command line and the kiosk's log share them).
#include "speed/speed_kind.hpp"

#include <array>
#include <optional>
#include <string_view>

namespace steerseg::workflow {

inline constexpr std::array<speed::SpeedKind, 3> kSpeedKinds{
    speed::SpeedKind::Threshold, speed::SpeedKind::Edge, speed::SpeedKind::Classify};

constexpr std::string_view speedName(speed::SpeedKind kind) {
    switch (kind) {
    case speed::SpeedKind::Threshold:
        return "threshold";
    case speed::SpeedKind::Edge:
        return "edge";
    case speed::SpeedKind::Classify:
        return "classify";
    }
    return "unknown";
}

constexpr std::optional<speed::SpeedKind> speedFromName(std::string_view name) {
    for (speed::SpeedKind k : kSpeedKinds) {
        if (speedName(k) == name) {
            return k;
        }
    }
    return std::nullopt;
}

constexpr bool validSpeed(speed::SpeedKind kind) {
    return speedName(kind) != "unknown";
}

} // namespace steerseg::workflow
