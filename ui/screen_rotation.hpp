#pragma once

// The display may be mounted rotated (config rotation 0, 90, 180 or 270 degrees clockwise):
// the kiosk composes the logical (upright) screen and rotates it on present, and pointer
// events arrive in the physical framebuffer's pixels. This maps between the two.
#include "platform/input_event.hpp"

#include <glm/glm.hpp>

namespace steerseg::ui {

class ScreenRotation {
  public:
    // `degrees`: how far the logical image is turned clockwise to appear upright on the
    // physical screen of `physicalWidth` x `physicalHeight`. Throws std::invalid_argument for
    // anything but 0, 90, 180, 270 (or -90, 360 ...: taken modulo 360) and non-positive sizes.
    ScreenRotation(int degrees, int physicalWidth, int physicalHeight);

    [[nodiscard]] int degrees() const { return degrees_; }
    [[nodiscard]] glm::ivec2 physicalSize() const { return physical_; }
    [[nodiscard]] glm::ivec2 logicalSize() const;

    // Continuous pixel coordinates (a pixel's centre is at +0.5): pixel centres map to pixel
    // centres, and the two are inverse to each other.
    [[nodiscard]] glm::dvec2 toLogical(const glm::dvec2& physical) const;
    [[nodiscard]] glm::dvec2 toPhysical(const glm::dvec2& logical) const;
    // The same event with its position in logical pixels (pointer kinds; others unchanged).
    [[nodiscard]] platform::InputEvent toLogical(const platform::InputEvent& event) const;

  private:
    int degrees_ = 0;
    glm::ivec2 physical_{0};
};

} // namespace steerseg::ui
