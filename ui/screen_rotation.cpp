#include "ui/screen_rotation.hpp"

#include <stdexcept>
#include <string>

namespace steerseg::ui {

ScreenRotation::ScreenRotation(int degrees, int physicalWidth, int physicalHeight)
    : degrees_(((degrees % 360) + 360) % 360), physical_(physicalWidth, physicalHeight) {
    if (degrees_ % 90 != 0) {
        throw std::invalid_argument("display rotation " + std::to_string(degrees) +
                                    " is not one of 0, 90, 180, 270");
    }
    if (physicalWidth <= 0 || physicalHeight <= 0) {
        throw std::invalid_argument("display size " + std::to_string(physicalWidth) + "x" +
                                    std::to_string(physicalHeight) + " is not positive");
    }
}

glm::ivec2 ScreenRotation::logicalSize() const {
    return degrees_ % 180 == 0 ? physical_ : glm::ivec2(physical_.y, physical_.x);
}

// With the logical image of size (W, H) turned clockwise by 90 degrees, its top left corner
// lands at the physical top right: physical = (H - y, x).
glm::dvec2 ScreenRotation::toPhysical(const glm::dvec2& p) const {
    const glm::dvec2 size(logicalSize());
    switch (degrees_) {
    case 90:
        return {size.y - p.y, p.x};
    case 180:
        return {size.x - p.x, size.y - p.y};
    case 270:
        return {p.y, size.x - p.x};
    default:
        return p;
    }
}

glm::dvec2 ScreenRotation::toLogical(const glm::dvec2& p) const {
    const glm::dvec2 size(logicalSize());
    switch (degrees_) {
    case 90:
        return {p.y, size.y - p.x};
    case 180:
        return {size.x - p.x, size.y - p.y};
    case 270:
        return {size.x - p.y, p.x};
    default:
        return p;
    }
}

platform::InputEvent ScreenRotation::toLogical(const platform::InputEvent& event) const {
    using Kind = platform::InputEvent::Kind;
    if (event.kind != Kind::PointerDown && event.kind != Kind::PointerMove &&
        event.kind != Kind::PointerUp && event.kind != Kind::Wheel) {
        return event;
    }
    platform::InputEvent out = event;
    const glm::dvec2 logical = toLogical(glm::dvec2(event.x, event.y));
    out.x = static_cast<float>(logical.x);
    out.y = static_cast<float>(logical.y);
    return out;
}

} // namespace steerseg::ui
