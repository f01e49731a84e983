// exports::writeImage (render --output, the kiosk's `frame`) under real write failures: a file
// size limit that stops the bytes halfway (as a full disk does), a missing folder, a read-only
// one and a folder in the way. Each must throw files::WriteError in one line, leave an existing
// picture as it was and leave no temporary file behind.
#include "exports/image_file.hpp"
#include "files/file_error.hpp"
#include "support/test_data.hpp"
#include "support/unprivileged.hpp"

#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

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

std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string text(std::filesystem::file_size(path), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    return text;
}

std::size_t entries(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir), {}));
}

std::string messageOf(const std::function<void()>& write) {
    try {
        write();
    } catch (const files::WriteError& e) {
        return e.what();
    }
    return "";
}

void writeOld(const std::filesystem::path& path) {
    std::ofstream(path, std::ios::binary) << "the previous picture";
}

// The child may write files of at most 4 KiB: the PNG's bytes stop there, as on a full disk.
std::string messageUnderSizeLimit(const std::filesystem::path& target) {
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) {
        return "no pipe";
    }
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(pipeFds[0]);
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const std::string m = messageOf([&] { exports::writeImage(target, noisyPicture()); });
        const ssize_t written = ::write(pipeFds[1], m.data(), m.size());
        ::_exit(written == static_cast<ssize_t>(m.size()) ? 0 : 1);
    }
    ::close(pipeFds[1]);
    std::string m;
    char buffer[512];
    for (ssize_t n = 0; (n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0;) {
        m.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    return m;
}

TEST(FaultsImageWrite, WritesAPictureThatReadsBack) {
    const auto dir = tempDir("faults-image-ok");
    const RgbaImage picture = noisyPicture();
    writeOld(dir / "frame.png");
    exports::writeImage(dir / "frame.png", picture);
    EXPECT_EQ(exports::readImage(dir / "frame.png").pixels, picture.pixels);
    EXPECT_EQ(entries(dir), 1u);
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
    EXPECT_EQ(entries(dir), 1u);
}

TEST(FaultsImageWrite, MissingFolderIsNamed) {
    const auto dir = tempDir("faults-image-missing");
    const auto folder = dir / "not-there";
    const std::string m =
        messageOf([&] { exports::writeImage(folder / "frame.png", noisyPicture()); });
    EXPECT_NE(m.find("the folder " + folder.string() + " does not exist"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(FaultsImageWrite, AFolderInTheWayIsNamed) {
    const auto dir = tempDir("faults-image-folder");
    std::filesystem::create_directory(dir / "frame.png");
    const std::string m =
        messageOf([&] { exports::writeImage(dir / "frame.png", noisyPicture()); });
    EXPECT_NE(m.find("a folder of that name is in the way"), std::string::npos) << m;
    EXPECT_EQ(entries(dir), 1u);
}

TEST(FaultsImageWrite, ReadOnlyFolderLeavesTheOldPicture) {
    const auto dir = tempDir("faults-image-readonly");
    writeOld(dir / "frame.png");
    std::filesystem::permissions(
        dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                 std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
    const std::string m = runUnprivileged(
        [&] { return messageOf([&] { exports::writeImage(dir / "frame.png", noisyPicture()); }); });
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
    EXPECT_NE(m.find("the folder " + dir.string() + " is not writable"), std::string::npos) << m;
    EXPECT_EQ(readText(dir / "frame.png"), "the previous picture");
    EXPECT_EQ(entries(dir), 1u);
}

} // namespace
} // namespace steerseg::test
