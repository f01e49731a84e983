// The window backend for real, on an X server (CTest runs this binary under xvfb-run): the
// context is GLES 3.1+, a cleared frame reaches the X screen, and input injected into the X
// server with xdotool comes back from pollEvents in framebuffer pixels.
#include "platform/gl_readback.hpp"
#include "platform/window/window_display.hpp"
#include "support/x11_probe.hpp"

#include <GLES3/gl31.h>
#include <array>
#include <chrono>
#include <cstdlib>
#include <gtest/gtest.h>
#include <iostream>
#include <memory>
#include <string>
#include <thread>

namespace steerseg::test {
namespace {

using platform::InputEvent;
using Clock = std::chrono::steady_clock;

constexpr auto kTimeout = std::chrono::seconds(5);

using Rgb = std::array<int, 3>;

bool near(const Rgb& a, const Rgb& b) {
    for (std::size_t i = 0; i < 3; ++i) {
        if (std::abs(a[i] - b[i]) > 2) {
            return false;
        }
    }
    return true;
}

void drawFrame(platform::Display& display, float r, float g, float b) {
    glBindFramebuffer(GL_FRAMEBUFFER, display.framebuffer());
    glViewport(0, 0, display.info().width, display.info().height);
    glClearColor(r, g, b, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT);
}

class WindowDisplayTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_NE(std::getenv("DISPLAY"), nullptr)
            << "no X display: CTest runs this test under xvfb-run";
        platform::DisplayOptions options;
        options.width = 320;
        options.height = 200;
        options.title = "steerseg window test";
        display_ = platform::openWindowDisplay(options);
        xwindow_ = currentSdlXWindow();
        ASSERT_NE(xwindow_, 0UL) << "SDL's window is not an X11 window";
        ASSERT_TRUE(x_.connected());
    }

    // Presents frames of one colour until the X screen shows it (the window maps asynchronously).
    bool showUntilVisible(const Rgb& colour) {
        const auto deadline = Clock::now() + kTimeout;
        std::vector<InputEvent> ignored;
        while (Clock::now() < deadline) {
            drawFrame(*display_, static_cast<float>(colour[0]) / 255.0F,
                      static_cast<float>(colour[1]) / 255.0F,
                      static_cast<float>(colour[2]) / 255.0F);
            display_->present();
            display_->pollEvents(ignored);
            if (near(x_.pixel(xwindow_, 160, 100), colour)) {
                return true;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return false;
    }

    // Polls until `done` holds for the events so far, or the timeout.
    template <typename Pred> std::vector<InputEvent> pollUntil(Pred done) {
        std::vector<InputEvent> events;
        const auto deadline = Clock::now() + kTimeout;
        while (!done(events) && Clock::now() < deadline) {
            display_->pollEvents(events);
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return events;
    }

    std::unique_ptr<platform::Display> display_;
    unsigned long xwindow_ = 0;
    X11Probe x_;
};

const InputEvent* find(const std::vector<InputEvent>& events, InputEvent::Kind kind) {
    for (const InputEvent& e : events) {
        if (e.kind == kind) {
            return &e;
        }
    }
    return nullptr;
}

void xdotool(const std::string& arguments) {
    const std::string command = "xdotool " + arguments;
    ASSERT_EQ(std::system(command.c_str()), 0) << command << " failed (is xdotool installed?)";
}

TEST_F(WindowDisplayTest, HasAnEs31ContextAndItsSize) {
    const std::string version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    EXPECT_EQ(version.rfind("OpenGL ES 3.", 0), 0U) << version;
    EXPECT_NE(version.rfind("OpenGL ES 3.0", 0), 0U) << version;
    EXPECT_EQ(display_->info().width, 320);
    EXPECT_EQ(display_->info().height, 200);
    EXPECT_EQ(display_->framebuffer(), 0U);
    EXPECT_GT(display_->info().dpi, 0.0);
    EXPECT_NE(display_->info().description.find("window 320x200"), std::string::npos)
        << display_->info().description;
    std::cout << display_->info().description << "\n";
}

TEST_F(WindowDisplayTest, ClearedFrameReachesTheXScreen) {
    const Rgb teal{51, 153, 204};
    ASSERT_TRUE(showUntilVisible(teal)) << "the X screen never showed the cleared colour";
    // A second colour proves the screen follows the frames, not a colour left from the first.
    const Rgb orange{230, 102, 26};
    ASSERT_TRUE(showUntilVisible(orange));
    // The whole window on the X screen is the frame: orange with a white top row, the same
    // rows that readFramebuffer returns from the back buffer before present.
    drawFrame(*display_, 230.0F / 255.0F, 102.0F / 255.0F, 26.0F / 255.0F);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 199, 320, 1);
    glClearColor(1.0F, 1.0F, 1.0F, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    const std::vector<std::uint8_t> drawn = platform::readFramebuffer(0, 320, 200);
    display_->present();
    std::vector<std::uint8_t> shown;
    const auto deadline = Clock::now() + kTimeout;
    while (shown != drawn && Clock::now() < deadline) {
        shown = x_.capture(xwindow_, 320, 200);
    }
    ASSERT_EQ(shown.size(), drawn.size());
    EXPECT_TRUE(shown == drawn) << "the X screen differs from the frame read back";
    EXPECT_EQ(shown[0], 255);
    EXPECT_EQ(shown[320U * 4U + 2U], 26);

    // The back buffer read before present holds what was drawn, top row first.
    drawFrame(*display_, 0.0F, 0.0F, 1.0F);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 199, 320, 1); // GL's top row
    glClearColor(1.0F, 0.0F, 0.0F, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    const std::vector<std::uint8_t> rgba = platform::readFramebuffer(0, 320, 200);
    ASSERT_EQ(rgba.size(), 320U * 200U * 4U);
    EXPECT_EQ(rgba[0], 255);
    EXPECT_EQ(rgba[2], 0);
    EXPECT_EQ(rgba[(320U * 4U) + 0], 0);
    EXPECT_EQ(rgba[(320U * 4U) + 2], 255);
    display_->present();
}

TEST_F(WindowDisplayTest, InjectedClickAndKeyComeBackInFramebufferPixels) {
    ASSERT_TRUE(showUntilVisible({128, 128, 128}));
    const std::string id = std::to_string(xwindow_);
    xdotool("mousemove --window " + id + " 100 60");
    xdotool("click 1");
    // Keys go to the window under the pointer (Xvfb has no window manager to give focus).
    xdotool("key space");
    const auto events = pollUntil([](const std::vector<InputEvent>& so_far) {
        bool up = false;
        bool key = false;
        for (const InputEvent& e : so_far) {
            up = up || e.kind == InputEvent::Kind::PointerUp;
            key = key || (e.kind == InputEvent::Kind::KeyUp && e.key == "space");
        }
        return up && key;
    });
    const InputEvent* down = find(events, InputEvent::Kind::PointerDown);
    const InputEvent* up = find(events, InputEvent::Kind::PointerUp);
    const InputEvent* key = find(events, InputEvent::Kind::KeyDown);
    ASSERT_NE(down, nullptr) << "no PointerDown from xdotool click";
    ASSERT_NE(up, nullptr) << "no PointerUp from xdotool click";
    EXPECT_EQ(down->pointer, 0);
    EXPECT_NEAR(down->x, 100.0F, 1.0F);
    EXPECT_NEAR(down->y, 60.0F, 1.0F);
    EXPECT_NEAR(up->x, 100.0F, 1.0F);
    EXPECT_NEAR(up->y, 60.0F, 1.0F);
    EXPECT_LE(down->time, up->time);
    ASSERT_NE(key, nullptr) << "no KeyDown from xdotool key space";
    EXPECT_EQ(key->key, "space");
    EXPECT_FALSE(key->ctrl);
}

TEST_F(WindowDisplayTest, ClosingTheWindowGivesQuit) {
    ASSERT_TRUE(showUntilVisible({10, 200, 10}));
    ASSERT_TRUE(x_.requestClose(xwindow_));
    const auto events = pollUntil([](const std::vector<InputEvent>& so_far) {
        return find(so_far, InputEvent::Kind::Quit) != nullptr;
    });
    EXPECT_NE(find(events, InputEvent::Kind::Quit), nullptr);
}

} // namespace
} // namespace steerseg::test
