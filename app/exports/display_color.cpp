#include "exports/display_color.hpp"

#include <algorithm>
#include <cmath>

namespace steerseg::exports {

std::array<std::uint16_t, 3> dicomLabFromRgb(const glm::dvec3& rgb) {
    const auto linear = [](double c) {
        c = std::clamp(c, 0.0, 1.0);
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    const glm::dvec3 l(linear(rgb.r), linear(rgb.g), linear(rgb.b));
    // sRGB's primaries to XYZ, over the D65 white (CIE 15, as scikit-image's rgb2lab).
    const glm::dvec3 xyz(0.412453 * l.r + 0.357580 * l.g + 0.180423 * l.b,
                         0.212671 * l.r + 0.715160 * l.g + 0.072169 * l.b,
                         0.019334 * l.r + 0.119193 * l.g + 0.950227 * l.b);
    const glm::dvec3 white(0.95047, 1.0, 1.08883);
    const auto f = [](double t) {
        constexpr double delta = 6.0 / 29.0;
        return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
    };
    const glm::dvec3 fxyz(f(xyz.x / white.x), f(xyz.y / white.y), f(xyz.z / white.z));
    const double lightness = 116.0 * fxyz.y - 16.0;
    const double a = 500.0 * (fxyz.x - fxyz.y);
    const double b = 200.0 * (fxyz.y - fxyz.z);
    const auto scaled = [](double v, double lo, double hi) {
        return static_cast<std::uint16_t>(
            std::lround(std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * 65535.0));
    };
    return {scaled(lightness, 0.0, 100.0), scaled(a, -128.0, 127.0), scaled(b, -128.0, 127.0)};
}

} // namespace steerseg::exports
