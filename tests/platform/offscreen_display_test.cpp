// The offscreen display: a framebuffer of the configured virtual size on the EGL context, the
// frames read back top row first, and a bad size refused in one line.
#include "platform/egl/offscreen_display.hpp"
#include "platform/gl_readback.hpp"

#include <GLES3/gl31.h>
#include <gtest/gtest.h>
#include <string>

namespace steerseg::test {
namespace {

TEST(OffscreenDisplay, DrawsIntoItsFramebufferOfTheVirtualSize) {
    platform::DisplayOptions options;
    options.width = 64;
    options.height = 48;
    const auto display = platform::openOffscreenDisplay(options);
    EXPECT_EQ(display->info().width, 64);
    EXPECT_EQ(display->info().height, 48);
    EXPECT_DOUBLE_EQ(display->info().dpi, 96.0);
    EXPECT_DOUBLE_EQ(display->info().refreshHz, 0.0);
    EXPECT_EQ(display->info().description.rfind("offscreen 64x48 (EGL ", 0), 0U)
        << display->info().description;
    ASSERT_NE(display->framebuffer(), 0U);

    // Green everywhere, red on GL's bottom row: the readback's last row.
    glBindFramebuffer(GL_FRAMEBUFFER, display->framebuffer());
    glViewport(0, 0, 64, 48);
    glClearColor(0.0F, 1.0F, 0.0F, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 64, 1);
    glClearColor(1.0F, 0.0F, 0.0F, 1.0F);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    display->present();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    const std::vector<std::uint8_t> rgba =
        platform::readFramebuffer(display->framebuffer(), 64, 48);
    ASSERT_EQ(rgba.size(), 64U * 48U * 4U);
    const std::size_t lastRow = 47U * 64U * 4U;
    EXPECT_EQ(rgba[0], 0);
    EXPECT_EQ(rgba[1], 255);
    EXPECT_EQ(rgba[3], 255);
    EXPECT_EQ(rgba[lastRow], 255);
    EXPECT_EQ(rgba[lastRow + 1], 0);
    // The caller's pack alignment and read binding are left as they were.
    GLint alignment = 0;
    GLint read = -1;
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    EXPECT_EQ(alignment, 8);
    EXPECT_EQ(read, 0);

    std::vector<platform::InputEvent> events;
    display->pollEvents(events);
    EXPECT_TRUE(events.empty());
}

TEST(OffscreenDisplay, RefusesABadSize) {
    platform::DisplayOptions options;
    options.width = 0;
    try {
        (void)platform::openOffscreenDisplay(options);
        ADD_FAILURE() << "opened a 0-pixel screen";
    } catch (const platform::DisplayError& e) {
        EXPECT_EQ(std::string(e.what()), "offscreen: bad screen size 0x800 (1..8192 each)");
    }
}

} // namespace
} // namespace steerseg::test
