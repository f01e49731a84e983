#pragma once

// SDL events -> InputEvent, apart from the window so the mapping is tested on made-up events
// without a display.
#include "platform/input_event.hpp"

#include <SDL.h>
#include <array>
#include <string>
#include <vector>

namespace steerseg::platform::window {

// The lower-case name of input_event.hpp for an SDL key, "" for keys the kiosk does not use.
std::string keyName(SDL_Keycode key);

class SdlInputMapper {
  public:
    // The window's size in screen coordinates and its drawable's in pixels; they differ on
    // high-DPI desktops, and events are reported in drawable pixels.
    void setSizes(int windowWidth, int windowHeight, int drawableWidth, int drawableHeight);

    // Appends what `event` means (nothing for events the kiosk does not use); `now` stamps it.
    // `mouseX/mouseY` (window coordinates) place a wheel event.
    void map(const SDL_Event& event, double now, int mouseX, int mouseY,
             std::vector<InputEvent>& out);

  private:
    // Finger slot 1..kMaxFingers for an SDL finger id; 0 when every slot is taken.
    int slotOf(SDL_FingerID finger, bool allocate);

    static constexpr int kMaxFingers = 10;
    std::array<SDL_FingerID, kMaxFingers> fingers_{};
    std::array<bool, kMaxFingers> used_{};
    float scaleX_ = 1.0F;
    float scaleY_ = 1.0F;
    int drawableWidth_ = 1;
    int drawableHeight_ = 1;
};

} // namespace steerseg::platform::window
