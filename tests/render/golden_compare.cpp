#include "golden_compare.hpp"

#include "exports/image_file.hpp"
#include "render_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace steerseg::test {

namespace {

int countYellow(const RgbaImage& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            n += isYellow(image.at(x, y)) ? 1 : 0;
        }
    }
    return n;
}

} // namespace

GoldenResult compareImages(const std::string& name, const RgbaImage& expected,
                           const RgbaImage& actual, const GoldenTolerance& tolerance) {
    GoldenResult r;
    if (expected.width != actual.width || expected.height != actual.height) {
        r.message = name + ": size " + std::to_string(actual.width) + "x" +
                    std::to_string(actual.height) + " differs from the golden's " +
                    std::to_string(expected.width) + "x" + std::to_string(expected.height);
        return r;
    }
    r.diff = {actual.width, actual.height, {}};
    r.diff.pixels.assign(actual.pixels.size(), 0);
    std::size_t differing = 0;
    int worst = 0;
    int worstAlpha = 0;
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            int d = 0;
            for (int c = 0; c < 4; ++c) {
                const int e = std::abs(int(actual.at(x, y)[c]) - int(expected.at(x, y)[c]));
                d = std::max(d, e);
                worstAlpha = c == 3 ? std::max(worstAlpha, e) : worstAlpha;
            }
            worst = std::max(worst, d);
            std::uint8_t* out = r.diff.at(x, y);
            out[0] = static_cast<std::uint8_t>(std::min(255, d * 4));
            out[1] = d > tolerance.pixelTolerance ? 255 : 0;
            out[3] = 255;
            differing += d > tolerance.pixelTolerance ? 1 : 0;
        }
    }
    const double fraction =
        static_cast<double>(differing) / static_cast<double>(actual.width * actual.height);
    const int yellowExpected = countYellow(expected);
    const int yellowActual = countYellow(actual);
    const double yellowSlack = std::max<double>(
        kMinYellowSlack, tolerance.yellowCountTolerance * static_cast<double>(yellowExpected));
    const bool yellowOk = std::abs(yellowActual - yellowExpected) <= yellowSlack;
    std::ostringstream msg;
    msg << name << ":";
    if (fraction > tolerance.maxDifferingFraction) {
        msg << " " << differing << " pixels (" << fraction * 100.0 << "%) differ by more than "
            << tolerance.pixelTolerance << " in some channel (worst " << worst << ", alpha "
            << worstAlpha << ");";
    }
    if (!yellowOk) {
        msg << " " << yellowActual << " contour-yellow pixels where the golden has "
            << yellowExpected << " (a contour or clip line missing or moved);";
    }
    r.ok = fraction <= tolerance.maxDifferingFraction && yellowOk;
    r.message = r.ok ? "" : msg.str();
    return r;
}

std::filesystem::path goldenPath(const std::string& name) {
    // Compiled in (tests/render/CMakeLists.txt) so the check never depends on the environment.
    return std::filesystem::path(STEERSEG_GOLDEN_DIR) / (name + ".png");
}

GoldenResult compareGolden(const std::string& name, const RgbaImage& actual,
                           const GoldenTolerance& tolerance) {
    const std::filesystem::path golden = goldenPath(name);
    const char* update = std::getenv("STEERSEG_UPDATE_GOLDEN");
    if (update != nullptr && std::string(update) == "1") {
        std::filesystem::create_directories(golden.parent_path());
        exports::writeImage(golden, actual);
        return {true, "rewrote " + golden.string(), {}};
    }
    const std::filesystem::path here =
        std::filesystem::read_symlink("/proc/self/exe").parent_path(); // beside the binary
    const std::filesystem::path actualPath = here / (name + ".actual.png");
    const std::filesystem::path diffPath = here / (name + ".diff.png");
    if (!std::filesystem::exists(golden)) {
        exports::writeImage(actualPath, actual);
        return {false,
                "no golden " + golden.string() + " (actual written to " + actualPath.string() +
                    "; set STEERSEG_UPDATE_GOLDEN=1 to create it)",
                {}};
    }
    GoldenResult r = compareImages(name, exports::readImage(golden), actual, tolerance);
    if (!r.ok) {
        exports::writeImage(actualPath, actual);
        if (!r.diff.pixels.empty()) {
            exports::writeImage(diffPath, r.diff);
        }
        r.message += " actual: " + actualPath.string() + ", diff: " + diffPath.string() +
                     " (STEERSEG_UPDATE_GOLDEN=1 rewrites the golden)";
    }
    return r;
}

} // namespace steerseg::test
