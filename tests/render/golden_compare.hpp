#pragma once

// Golden-image comparison for the renderer tests (tests/golden/, docs/renderer.md).
#include "core/rgba_image.hpp"

#include <filesystem>
#include <string>

namespace steerseg::test {

struct GoldenTolerance {
    int pixelTolerance = 24;            // per channel, alpha included
    double maxDifferingFraction = 0.01; // of all pixels
    // The contour and the clip plane's intersection with the surface are thin yellow lines, well
    // under the differing-pixel budget: without their own check a picture could lose them and
    // still match. Their pixel count must be within this fraction of the golden's (and at
    // least kMinYellowSlack pixels either way), so a missing, doubled or misplaced line fails.
    double yellowCountTolerance = 0.2;
};
inline constexpr int kMinYellowSlack = 4;

struct GoldenResult {
    bool ok = false;
    std::string message;
    RgbaImage diff; // red: channel difference x4; green: past the tolerance
};

// Compares `actual` with `expected` (same size) as above; `name` prefixes the message.
GoldenResult compareImages(const std::string& name, const RgbaImage& expected,
                           const RgbaImage& actual, const GoldenTolerance& tolerance = {});

// tests/golden/NAME.png.
std::filesystem::path goldenPath(const std::string& name);

// compareImages against goldenPath(name). On a mismatch (or a missing golden) writes
// NAME.actual.png and NAME.diff.png beside the test binary and says so in the message; with
// STEERSEG_UPDATE_GOLDEN=1 rewrites the golden instead.
GoldenResult compareGolden(const std::string& name, const RgbaImage& actual,
                           const GoldenTolerance& tolerance = {});

} // namespace steerseg::test
