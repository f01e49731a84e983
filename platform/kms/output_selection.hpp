#pragma once

// Which connector and mode the KMS display drives: a pure function over the connectors as the
// DRM device lists them (or as a test records them), so every choice and every refusal is
// tested without hardware.
#include "platform/display.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::platform::kms {

struct ModeInfo {
    int width = 0;
    int height = 0;
    int refreshHz = 0; // rounded, as drmModeModeInfo::vrefresh
    bool preferred = false;
    std::string name; // "1920x1080"
};

struct ConnectorInfo {
    std::uint32_t id = 0;
    std::string name; // "HDMI-A-1", "eDP-1": the type name and its index among that type
    bool connected = false;
    int mmWidth = 0; // physical size; 0 where the monitor does not say
    int mmHeight = 0;
    std::vector<ModeInfo> modes;
};

// "1920x1080" or "1920x1080@60"; refreshHz 0 when no rate is given.
struct ModeRequest {
    int width = 0;
    int height = 0;
    int refreshHz = 0;
};

// Parses DisplayOptions::mode; throws DisplayError "kms: bad mode \"X\" (expected WxH or
// WxH@HZ)" for anything else.
ModeRequest parseModeRequest(const std::string& text);

struct OutputChoice {
    std::size_t connector = 0; // index into the list given to selectOutput
    std::size_t mode = 0;      // index into that connector's modes
};

// The configured connector (options.connector) or else the first connected one; on it the
// configured mode (options.mode; without a rate, the highest rate of that size) or else the
// preferred mode, else the largest. Throws DisplayError with one line:
// "kms: no connector named X (found: A, B)", "kms: connector X is not connected",
// "kms: no mode 1920x1080@60 on X (modes: ...)", "kms: no connected connector (found: ...)",
// "kms: connector X lists no modes".
OutputChoice selectOutput(const std::vector<ConnectorInfo>& connectors,
                          const DisplayOptions& options);

// Dots per inch along the width of `mode` on a panel `mmWidth` wide; nullopt where the panel
// does not report its size (projectors, some adapters report 0 or nonsense like 1 cm).
std::optional<double> dpiOf(const ModeInfo& mode, int mmWidth);

} // namespace steerseg::platform::kms
