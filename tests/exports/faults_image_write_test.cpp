// exports::writeImage (render --output, the kiosk's `frame`) under real write failures: a file
// size limit that stops the bytes halfway (as a full disk does), a missing folder, a read-only
// one and a folder in the way. Each must throw files::WriteError in one line, leave an existing
// picture as it was and leave no temporary file behind.
#include "exports/image_file.hpp"
#include "files/file_error.hpp"
#include "support/test_data.hpp"
#include "support/unprivileged.hpp"
#include "support/write_faults.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

// Noise, so that the PNG stays larger than the child's file size limit after compression;
// opaque as a rendered view is (PNG's alpha would be unpremultiplied on the way back).
RgbaImage noisyPicture() {
    RgbaImage image{128, 128, {}};
    image.pixels.resize(128u * 128u * 4u);
    std::uint32_t state = 12345;
    for (std::size_t n = 0; n < image.pixels.size(); ++n) {
        state = state * 1664525u + 1013904223u;
        image.pixels[n] = n % 4 == 3 ? 255 : static_cast<std::uint8_t>(state >> 24);
    }
    return image;
}

void writeOld(const std::filesystem::path& path) {
    std::ofstream(path, std::ios::binary) << "the previous picture";
}

// The child may write files of at most 4 KiB: the PNG's bytes stop there, as on a full disk.
std::string messageUnderSizeLimit(const std::filesystem::path& target) {
    return writeErrorUnderSizeLimit([&] { exports::writeImage(target, noisyPicture()); }, 4096);
}

TEST(FaultsImageWrite, WritesAPictureThatReadsBack) {
    const auto dir = tempDir("faults-image-ok");
    const RgbaImage picture = noisyPicture();
    writeOld(dir / "frame.png");
    exports::writeImage(dir / "frame.png", picture);
    EXPECT_EQ(exports::readImage(dir / "frame.png").pixels, picture.pixels);
    EXPECT_EQ(entryCount(dir), 1u);
}

TEST(FaultsImageWrite, FailingHalfwayLeavesTheOldPictureAndNoTemporary) {
    const auto dir = tempDir("faults-image-limit");
    const auto target = dir / "frame.png";
    writeOld(target);
    const std::string m = messageUnderSizeLimit(target);
    EXPECT_NE(m.find(target.string() + ": the file is larger than this system lets the program "
                                       "write"),
              std::string::npos)
        << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_EQ(readText(target), "the previous picture");
    EXPECT_EQ(entryCount(dir), 1u);
}

TEST(FaultsImageWrite, MissingFolderIsNamed) {
    const auto dir = tempDir("faults-image-missing");
    const auto folder = dir / "not-there";
    const std::string m =
        writeErrorOf([&] { exports::writeImage(folder / "frame.png", noisyPicture()); });
    EXPECT_NE(m.find("the folder " + folder.string() + " does not exist"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(FaultsImageWrite, AFolderInTheWayIsNamed) {
    const auto dir = tempDir("faults-image-folder");
    std::filesystem::create_directory(dir / "frame.png");
    const std::string m =
        writeErrorOf([&] { exports::writeImage(dir / "frame.png", noisyPicture()); });
    EXPECT_NE(m.find("a folder of that name is in the way"), std::string::npos) << m;
    EXPECT_EQ(entryCount(dir), 1u);
}

TEST(FaultsImageWrite, ReadOnlyFolderLeavesTheOldPicture) {
    const auto dir = tempDir("faults-image-readonly");
    writeOld(dir / "frame.png");
    std::filesystem::permissions(
        dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                 std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
    const std::string m = runUnprivileged([&] {
        return writeErrorOf([&] { exports::writeImage(dir / "frame.png", noisyPicture()); });
    });
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
    EXPECT_NE(m.find("the folder " + dir.string() + " is not writable"), std::string::npos) << m;
    EXPECT_EQ(readText(dir / "frame.png"), "the previous picture");
    EXPECT_EQ(entryCount(dir), 1u);
}

} // namespace
} // namespace steerseg::test
