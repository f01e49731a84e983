#pragma once

// Which data term drives the surface. Plain data and header-only: the session layer, the
// workflow, the config and the command line name a speed without linking any GL code.
#include <array>
#include <optional>
#include <string_view>

namespace steerseg::model {

// The data term D of F = alpha * D - (1 - alpha) * H (docs/speed.md):
//   Threshold  eps - |I - T|            (Lefohn et al. 2003), I the scan or its smoothed copy
//   Edge       g * (eps - |I - T|)      g = 1 / (1 + (|grad I_s| / kappa)^2), I_s smoothed
//   Classify   P(inside) - P(outside)   a classifier trained on the operator's examples
enum class SpeedKind { Threshold, Edge, Classify };

inline constexpr std::array<SpeedKind, 3> kSpeedKinds{SpeedKind::Threshold, SpeedKind::Edge,
                                                      SpeedKind::Classify};

// "threshold", "edge", "classify": the command line, the report, the config, the scripts and
// the audit log all use these names.
constexpr std::string_view speedKindName(SpeedKind kind) {
    switch (kind) {
    case SpeedKind::Threshold:
        return "threshold";
    case SpeedKind::Edge:
        return "edge";
    case SpeedKind::Classify:
        return "classify";
    }
    return "unknown";
}

constexpr std::optional<SpeedKind> parseSpeedKind(std::string_view name) {
    for (const SpeedKind k : kSpeedKinds) {
        if (speedKindName(k) == name) {
            return k;
        }
    }
    return std::nullopt;
}

// False for a value outside the enum (a cast from a corrupt number).
constexpr bool validSpeedKind(SpeedKind kind) {
    return speedKindName(kind) != "unknown";
}

} // namespace steerseg::model
