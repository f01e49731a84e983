// The KMS display for real, where this machine has a DRM device with a monitor and nothing else
// holds it (an appliance, a developer's console VT); it skips with the reason elsewhere.
#include "platform/kms/kms_display.hpp"

#include <GLES3/gl31.h>
#include <chrono>
#include <filesystem>
#include <gtest/gtest.h>
#include <memory>
#include <string>

namespace steerseg::test {
namespace {

std::unique_ptr<platform::Display> openOrSkipReason(std::string& reason) {
    if (!std::filesystem::exists("/dev/dri/card0")) {
        reason = "no /dev/dri/card0: this machine has no DRM device";
        return nullptr;
    }
    try {
        return platform::openKmsDisplay(platform::DisplayOptions{});
    } catch (const platform::DisplayError& e) {
        const std::string message = e.what();
        // A device without a monitor, or held by a display server, cannot be tested here; any
        // other refusal is a failure.
        if (message.find("no connected connector") != std::string::npos ||
            message.find("not DRM master") != std::string::npos ||
            message.find("cannot open") != std::string::npos) {
            reason = message;
            return nullptr;
        }
        throw;
    }
}

TEST(KmsDisplay, PresentsFramesPacedByPageFlips) {
    std::string reason;
    const auto display = openOrSkipReason(reason);
    if (!display) {
        GTEST_SKIP() << reason;
    }
    const platform::DisplayInfo& info = display->info();
    EXPECT_GT(info.width, 0);
    EXPECT_GT(info.height, 0);
    EXPECT_GT(info.dpi, 0.0);
    EXPECT_EQ(info.description.rfind("kms /dev/dri/", 0), 0U) << info.description;
    constexpr int kFrames = 30;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < kFrames; ++frame) {
        const float shade = static_cast<float>(frame) / kFrames;
        glBindFramebuffer(GL_FRAMEBUFFER, display->framebuffer());
        glViewport(0, 0, info.width, info.height);
        glClearColor(shade, 0.2F, 1.0F - shade, 1.0F);
        glClear(GL_COLOR_BUFFER_BIT);
        display->present();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    if (info.refreshHz > 0.0) {
        // Flips pace the loop: not faster than the refresh (with slack for the first frame),
        // and never stuck for the 100 ms flip timeout on every frame.
        EXPECT_GE(seconds, (kFrames - 2) / info.refreshHz) << info.description;
    }
    EXPECT_LT(seconds, kFrames * 0.1) << info.description;
}

} // namespace
} // namespace steerseg::test
