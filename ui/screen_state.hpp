#pragma once

// The screen as the kiosk drew it this frame: where each part went and, for the slice views,
// which frame each image shows (what a tap maps through and what the captions name).
#include "ui/layout.hpp"
#include "ui/slice_mapping.hpp"

#include <optional>

namespace steerseg::ui {

struct ScreenState {
    Layout layout;
    std::optional<SliceView> slice1; // absent: not drawn (no scan)
    std::optional<SliceView> slice2;
};

} // namespace steerseg::ui
