// The window backend's event mapping on made-up SDL events (no display needed): mouse and
// touch become pointers in drawable pixels, touch is not seen twice, keys get their names.
#include "platform/window/sdl_input.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using platform::InputEvent;
using platform::window::keyName;
using platform::window::SdlInputMapper;

SDL_Event mouseButton(Uint32 type, int x, int y, Uint32 which = 0, Uint8 button = SDL_BUTTON_LEFT) {
    SDL_Event e{};
    e.type = type;
    e.button.which = which;
    e.button.button = button;
    e.button.x = x;
    e.button.y = y;
    return e;
}

SDL_Event finger(Uint32 type, SDL_FingerID id, float x, float y) {
    SDL_Event e{};
    e.type = type;
    e.tfinger.fingerId = id;
    e.tfinger.x = x;
    e.tfinger.y = y;
    return e;
}

SDL_Event key(Uint32 type, SDL_Keycode sym, Uint16 mod = KMOD_NONE, Uint8 repeat = 0) {
    SDL_Event e{};
    e.type = type;
    e.key.keysym.sym = sym;
    e.key.keysym.mod = mod;
    e.key.repeat = repeat;
    return e;
}

TEST(SdlInput, MouseIsPointerZeroInDrawablePixels) {
    SdlInputMapper mapper;
    mapper.setSizes(640, 400, 1280, 800); // a 2x high-DPI window
    std::vector<InputEvent> out;
    mapper.map(mouseButton(SDL_MOUSEBUTTONDOWN, 100, 50), 1.5, 0, 0, out);
    mapper.map(mouseButton(SDL_MOUSEBUTTONUP, 101, 52), 1.6, 0, 0, out);
    mapper.map(mouseButton(SDL_MOUSEBUTTONDOWN, 10, 10, 0, SDL_BUTTON_RIGHT), 1.7, 0, 0, out);
    ASSERT_EQ(out.size(), 2U);
    EXPECT_EQ(out[0].kind, InputEvent::Kind::PointerDown);
    EXPECT_EQ(out[0].pointer, 0);
    EXPECT_FLOAT_EQ(out[0].x, 200.0F);
    EXPECT_FLOAT_EQ(out[0].y, 100.0F);
    EXPECT_DOUBLE_EQ(out[0].time, 1.5);
    EXPECT_EQ(out[1].kind, InputEvent::Kind::PointerUp);
    EXPECT_FLOAT_EQ(out[1].x, 202.0F);
}

TEST(SdlInput, FingersGetSlotsAndTheirMouseEchoIsDropped) {
    SdlInputMapper mapper;
    mapper.setSizes(800, 600, 800, 600);
    std::vector<InputEvent> out;
    mapper.map(finger(SDL_FINGERDOWN, 9001, 0.5F, 0.25F), 0.0, 0, 0, out);
    mapper.map(mouseButton(SDL_MOUSEBUTTONDOWN, 400, 150, SDL_TOUCH_MOUSEID), 0.0, 0, 0, out);
    mapper.map(finger(SDL_FINGERDOWN, 42, 0.1F, 0.1F), 0.0, 0, 0, out);
    mapper.map(finger(SDL_FINGERMOTION, 9001, 0.75F, 0.5F), 0.0, 0, 0, out);
    mapper.map(finger(SDL_FINGERUP, 9001, 0.75F, 0.5F), 0.0, 0, 0, out);
    mapper.map(finger(SDL_FINGERDOWN, 7, 0.2F, 0.2F), 0.0, 0, 0, out); // reuses slot 1
    ASSERT_EQ(out.size(), 5U);
    EXPECT_EQ(out[0].kind, InputEvent::Kind::PointerDown);
    EXPECT_EQ(out[0].pointer, 1);
    EXPECT_FLOAT_EQ(out[0].x, 400.0F);
    EXPECT_FLOAT_EQ(out[0].y, 150.0F);
    EXPECT_EQ(out[1].pointer, 2);
    EXPECT_EQ(out[2].kind, InputEvent::Kind::PointerMove);
    EXPECT_EQ(out[2].pointer, 1);
    EXPECT_FLOAT_EQ(out[2].x, 600.0F);
    EXPECT_EQ(out[3].kind, InputEvent::Kind::PointerUp);
    EXPECT_EQ(out[3].pointer, 1);
    EXPECT_EQ(out[4].pointer, 1);
}

TEST(SdlInput, KeysHaveTheirNamesAndModifiers) {
    SdlInputMapper mapper;
    std::vector<InputEvent> out;
    mapper.map(key(SDL_KEYDOWN, SDLK_z, KMOD_LCTRL), 0.0, 0, 0, out);
    mapper.map(key(SDL_KEYDOWN, SDLK_z, KMOD_LCTRL, 1), 0.0, 0, 0, out); // auto-repeat
    mapper.map(key(SDL_KEYUP, SDLK_z), 0.0, 0, 0, out);
    mapper.map(key(SDL_KEYDOWN, SDLK_CAPSLOCK), 0.0, 0, 0, out); // not one of ours
    ASSERT_EQ(out.size(), 2U);
    EXPECT_EQ(out[0].kind, InputEvent::Kind::KeyDown);
    EXPECT_EQ(out[0].key, "z");
    EXPECT_TRUE(out[0].ctrl);
    EXPECT_FALSE(out[0].shift);
    EXPECT_EQ(out[1].kind, InputEvent::Kind::KeyUp);
    EXPECT_EQ(keyName(SDLK_SPACE), "space");
    EXPECT_EQ(keyName(SDLK_KP_ENTER), "enter");
    EXPECT_EQ(keyName(SDLK_7), "7");
    EXPECT_EQ(keyName(SDLK_F12), "f12");
    EXPECT_EQ(keyName(SDLK_KP_PLUS), "plus");
    EXPECT_EQ(keyName(SDLK_MINUS), "minus");
    EXPECT_EQ(keyName(SDLK_PAGEDOWN), "pagedown");
    EXPECT_EQ(keyName(SDLK_LSHIFT), "");
}

TEST(SdlInput, WheelAndQuit) {
    SdlInputMapper mapper;
    mapper.setSizes(100, 100, 200, 200);
    std::vector<InputEvent> out;
    SDL_Event wheel{};
    wheel.type = SDL_MOUSEWHEEL;
    wheel.wheel.preciseY = 1.0F;
    wheel.wheel.direction = SDL_MOUSEWHEEL_FLIPPED;
    mapper.map(wheel, 0.0, 30, 40, out);
    SDL_Event quit{};
    quit.type = SDL_QUIT;
    mapper.map(quit, 0.0, 0, 0, out);
    ASSERT_EQ(out.size(), 2U);
    EXPECT_EQ(out[0].kind, InputEvent::Kind::Wheel);
    EXPECT_FLOAT_EQ(out[0].wheel, -1.0F);
    EXPECT_FLOAT_EQ(out[0].x, 60.0F);
    EXPECT_FLOAT_EQ(out[0].y, 80.0F);
    EXPECT_EQ(out[1].kind, InputEvent::Kind::Quit);
}

} // namespace
} // namespace steerseg::test
