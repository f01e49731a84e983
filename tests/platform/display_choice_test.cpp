#include "platform/display.hpp"
#include "platform/display_choice.hpp"

#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using platform::defaultPlatform;
using platform::DisplayEnvironment;

TEST(DisplayChoice, ConfiguredBackendIsKept) {
    const DisplayEnvironment desktop{"", ":0"};
    EXPECT_EQ(defaultPlatform("kms", desktop), "kms");
    EXPECT_EQ(defaultPlatform("offscreen", desktop), "offscreen");
    EXPECT_EQ(defaultPlatform("window", DisplayEnvironment{}), "window");
}

TEST(DisplayChoice, AutoPicksAWindowWhereThereIsADisplay) {
    EXPECT_EQ(defaultPlatform("auto", DisplayEnvironment{"", ":0"}), "window");
    EXPECT_EQ(defaultPlatform("", DisplayEnvironment{"wayland-0", ""}), "window");
    EXPECT_EQ(defaultPlatform("auto", DisplayEnvironment{}), "offscreen");
    EXPECT_EQ(defaultPlatform("", DisplayEnvironment{}), "offscreen");
}

TEST(DisplayChoice, UnknownWordIsRefused) {
    try {
        (void)defaultPlatform("x11", DisplayEnvironment{});
        ADD_FAILURE() << "accepted x11";
    } catch (const platform::DisplayError& e) {
        EXPECT_STREQ(e.what(),
                     "unknown display platform \"x11\" (expected kms, window, offscreen or auto)");
    }
}

} // namespace
} // namespace steerseg::test
