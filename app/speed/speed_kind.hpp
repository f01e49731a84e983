#pragma once

// Which data term drives the surface, and the GPU inputs it reads. Plain data: the session
// layer, the workflow and the command line name a speed without any GL.
#include <optional>
#include <string_view>

namespace steerseg::speed {

// The data term D of F = alpha * D - (1 - alpha) * H (docs/speed.md):
//   Threshold  eps - |I - T|                 (Lefohn et al. 2003), I the scan or its smoothed copy
//   Edge       g * (eps - |I - T|)           g = 1 / (1 + (|grad I_s| / kappa)^2) from the smoothed scan
//   Classify   P(inside) - P(outside)        a classifier trained on the operator's examples
enum class SpeedKind { Threshold, Edge, Classify };

// "threshold", "edge", "classify" (the command line, the report, the config).
const char* speedKindName(SpeedKind kind);
std::optional<SpeedKind> parseSpeedKind(std::string_view name);

} // namespace steerseg::speed
