// Opening the KMS display where there is no DRM device to open: the one-line errors name the
// step, and nothing is left open or hangs.
#include "platform/kms/drm_device.hpp"
#include "platform/kms/kms_display.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace steerseg::test {
namespace {

std::string openError(const std::string& configured, const std::string& directory) {
    try {
        (void)platform::kms::openDrmDevice(configured, directory);
    } catch (const platform::DisplayError& e) {
        return e.what();
    }
    return "(opened)";
}

TEST(KmsOpen, MissingDirectoryNamesTheStep) {
    const std::string message = openError("", "/nonexistent/dri");
    EXPECT_EQ(message.rfind("kms: no DRM device (/nonexistent/dri/card*): ", 0), 0U) << message;
}

TEST(KmsOpen, DirectoryWithoutCardsNamesTheStep) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("steerseg-kms-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::filesystem::create_directories(dir / "by-path"); // not a card
    const std::string message = openError("", dir.string());
    std::filesystem::remove_all(dir);
    EXPECT_EQ(message, "kms: no DRM device (" + dir.string() + "/card*): none found");
}

TEST(KmsOpen, ConfiguredDeviceThatCannotBeOpened) {
    EXPECT_EQ(openError("/nonexistent/card7", "/dev/dri"),
              "kms: cannot open /nonexistent/card7: No such file or directory");
}

TEST(KmsOpen, AFileThatIsNoDrmDeviceIsRefused) {
    // /dev/null opens, but answers no DRM ioctl.
    const std::string message = openError("/dev/null", "/dev/dri");
    EXPECT_EQ(message.rfind("kms: /dev/null is no DRM device: ", 0), 0U) << message;
}

TEST(KmsOpen, DisplayOnThisMachineOpensOrNamesTheStep) {
    // Without /dev/dri (containers, CI) the display names the missing device; elsewhere it may
    // open for real (tests/platform/kms_display_test.cpp covers that) or refuse with a kms: line.
    try {
        const auto display = platform::openKmsDisplay(platform::DisplayOptions{});
        EXPECT_GT(display->info().width, 0);
    } catch (const platform::DisplayError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("kms: ", 0), 0U) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        if (!std::filesystem::exists("/dev/dri")) {
            EXPECT_EQ(message.rfind("kms: no DRM device (/dev/dri/card*): ", 0), 0U) << message;
        }
    }
}

} // namespace
} // namespace steerseg::test
