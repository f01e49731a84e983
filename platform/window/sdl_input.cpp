#include "platform/window/sdl_input.hpp"

namespace steerseg::platform::window {

std::string keyName(SDL_Keycode key) {
    if (key >= SDLK_a && key <= SDLK_z) {
        return std::string(1, static_cast<char>('a' + (key - SDLK_a)));
    }
    if (key >= SDLK_0 && key <= SDLK_9) {
        return std::string(1, static_cast<char>('0' + (key - SDLK_0)));
    }
    if (key >= SDLK_F1 && key <= SDLK_F12) {
        return "f" + std::to_string(1 + (key - SDLK_F1));
    }
    switch (key) {
    case SDLK_SPACE:
        return "space";
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
        return "enter";
    case SDLK_ESCAPE:
        return "escape";
    case SDLK_BACKSPACE:
        return "backspace";
    case SDLK_TAB:
        return "tab";
    case SDLK_LEFT:
        return "left";
    case SDLK_RIGHT:
        return "right";
    case SDLK_UP:
        return "up";
    case SDLK_DOWN:
        return "down";
    case SDLK_PAGEUP:
        return "pageup";
    case SDLK_PAGEDOWN:
        return "pagedown";
    // "+" shares its key with "=" on US and many other layouts; unshifted it still means plus.
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
        return "plus";
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
        return "minus";
    case SDLK_DELETE:
        return "delete";
    case SDLK_HOME:
        return "home";
    case SDLK_END:
        return "end";
    default:
        return "";
    }
}

void SdlInputMapper::setSizes(int windowWidth, int windowHeight, int drawableWidth,
                              int drawableHeight) {
    drawableWidth_ = drawableWidth > 0 ? drawableWidth : 1;
    drawableHeight_ = drawableHeight > 0 ? drawableHeight : 1;
    scaleX_ = windowWidth > 0 ? static_cast<float>(drawableWidth_) / static_cast<float>(windowWidth)
                              : 1.0F;
    scaleY_ = windowHeight > 0
                  ? static_cast<float>(drawableHeight_) / static_cast<float>(windowHeight)
                  : 1.0F;
}

int SdlInputMapper::slotOf(SDL_FingerID finger, bool allocate) {
    for (int i = 0; i < kMaxFingers; ++i) {
        if (used_[static_cast<std::size_t>(i)] && fingers_[static_cast<std::size_t>(i)] == finger) {
            return i + 1;
        }
    }
    if (!allocate) {
        return 0;
    }
    for (int i = 0; i < kMaxFingers; ++i) {
        if (!used_[static_cast<std::size_t>(i)]) {
            used_[static_cast<std::size_t>(i)] = true;
            fingers_[static_cast<std::size_t>(i)] = finger;
            return i + 1;
        }
    }
    return 0;
}

void SdlInputMapper::map(const SDL_Event& event, double now, int mouseX, int mouseY,
                         std::vector<InputEvent>& out) {
    InputEvent e;
    e.time = now;
    const SDL_Keymod mods = SDL_GetModState();
    e.ctrl = (mods & KMOD_CTRL) != 0;
    e.shift = (mods & KMOD_SHIFT) != 0;
    switch (event.type) {
    // Closing the (only) window arrives as SDL_QUIT too, as does SIGINT or SIGTERM; mapping the
    // window's own close event as well would report one close twice.
    case SDL_QUIT:
        e.kind = InputEvent::Kind::Quit;
        out.push_back(e);
        return;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
        // SDL repeats each touch as a mouse event; the finger event already reported it.
        if (event.button.which == SDL_TOUCH_MOUSEID || event.button.button != SDL_BUTTON_LEFT) {
            return;
        }
        e.kind = event.type == SDL_MOUSEBUTTONDOWN ? InputEvent::Kind::PointerDown
                                                   : InputEvent::Kind::PointerUp;
        e.x = static_cast<float>(event.button.x) * scaleX_;
        e.y = static_cast<float>(event.button.y) * scaleY_;
        out.push_back(e);
        return;
    case SDL_MOUSEMOTION:
        if (event.motion.which == SDL_TOUCH_MOUSEID) {
            return;
        }
        e.kind = InputEvent::Kind::PointerMove;
        e.x = static_cast<float>(event.motion.x) * scaleX_;
        e.y = static_cast<float>(event.motion.y) * scaleY_;
        out.push_back(e);
        return;
    case SDL_MOUSEWHEEL: {
        if (event.wheel.which == SDL_TOUCH_MOUSEID) {
            return;
        }
        float detents = event.wheel.preciseY;
        if (event.wheel.direction == SDL_MOUSEWHEEL_FLIPPED) {
            detents = -detents;
        }
        if (detents == 0.0F) {
            return; // a horizontal scroll
        }
        e.kind = InputEvent::Kind::Wheel;
        e.wheel = detents;
        e.x = static_cast<float>(mouseX) * scaleX_;
        e.y = static_cast<float>(mouseY) * scaleY_;
        out.push_back(e);
        return;
    }
    case SDL_FINGERDOWN:
    case SDL_FINGERMOTION:
    case SDL_FINGERUP: {
        const bool down = event.type == SDL_FINGERDOWN;
        const int slot = slotOf(event.tfinger.fingerId, down);
        if (slot == 0) {
            return; // an eleventh finger, or a finger that went down before the window existed
        }
        if (event.type == SDL_FINGERUP) {
            used_[static_cast<std::size_t>(slot - 1)] = false;
        }
        e.kind = down ? InputEvent::Kind::PointerDown
                      : (event.type == SDL_FINGERUP ? InputEvent::Kind::PointerUp
                                                    : InputEvent::Kind::PointerMove);
        e.pointer = slot;
        e.x = event.tfinger.x * static_cast<float>(drawableWidth_);
        e.y = event.tfinger.y * static_cast<float>(drawableHeight_);
        out.push_back(e);
        return;
    }
    case SDL_KEYDOWN:
    case SDL_KEYUP: {
        // A held key's repeats would toggle run/pause over and over; one press is one action.
        if (event.key.repeat != 0) {
            return;
        }
        e.key = keyName(event.key.keysym.sym);
        if (e.key.empty()) {
            return;
        }
        e.kind = event.type == SDL_KEYDOWN ? InputEvent::Kind::KeyDown : InputEvent::Kind::KeyUp;
        e.ctrl = (event.key.keysym.mod & KMOD_CTRL) != 0;
        e.shift = (event.key.keysym.mod & KMOD_SHIFT) != 0;
        out.push_back(e);
        return;
    }
    default:
        return;
    }
}

} // namespace steerseg::platform::window
