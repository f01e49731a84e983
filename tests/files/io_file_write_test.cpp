// files::writeFileAtomically's failures, each caused for real: a missing folder, a read-only one
// (not deniable as root), a full disk through /dev/full at the write loop's seam, and a file
// size limit (RLIMIT_FSIZE in a forked child: write() fails with EFBIG) through the whole path.
// After every failure no temporary file is left and an existing file is unchanged.
#include "files/file_write.hpp"
#include "scan/scan_reader.hpp"
#include "support/test_data.hpp"
#include "support/unprivileged.hpp"

#include <fcntl.h>
#include <fstream>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

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

void writeText(const std::filesystem::path& path, const std::string& text) {
    files::writeFileAtomically(path, {std::as_bytes(std::span(text))});
}

TEST(FileWrite, ReplacesTheFileAndLeavesNothingElse) {
    const auto dir = tempDir("write-replace");
    writeText(dir / "out.bin", "first");
    const std::string second = "second, longer";
    const std::string third = " and a second piece";
    files::writeFileAtomically(dir / "out.bin",
                               {std::as_bytes(std::span(second)), std::as_bytes(std::span(third))});
    EXPECT_EQ(readText(dir / "out.bin"), second + third);
    EXPECT_EQ(entries(dir), 1u);
    // A name with no folder part lands in the working directory.
    const auto cwd = std::filesystem::current_path();
    std::filesystem::current_path(dir);
    writeText("here.txt", "x");
    std::filesystem::current_path(cwd);
    EXPECT_EQ(readText(dir / "here.txt"), "x");
}

TEST(FileWrite, MissingFolderIsNamed) {
    const auto dir = tempDir("write-missing");
    const auto folder = dir / "not-there";
    const std::string m = messageOf([&] { writeText(folder / "m.nrrd", "x"); });
    EXPECT_NE(m.find("the folder " + folder.string() + " does not exist"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(FileWrite, AFolderInTheWayIsNamed) {
    const auto dir = tempDir("write-folder");
    std::filesystem::create_directory(dir / "m.nrrd");
    const std::string m = messageOf([&] { writeText(dir / "m.nrrd", "x"); });
    EXPECT_NE(m.find("a folder of that name is in the way"), std::string::npos) << m;
    EXPECT_EQ(entries(dir), 1u);
}

// As an operator's user would meet it (root is denied nothing: runUnprivileged drops to nobody,
// to whom the folder's "other" bits apply).
TEST(FileWrite, ReadOnlyFolderIsNamed) {
    const auto dir = tempDir("write-readonly");
    writeText(dir / "m.nrrd", "old");
    std::filesystem::permissions(
        dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                 std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
    const std::string m =
        runUnprivileged([&] { return messageOf([&] { writeText(dir / "m.nrrd", "new"); }); });
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
    EXPECT_NE(m.find("the folder " + dir.string() + " is not writable"), std::string::npos) << m;
    EXPECT_EQ(readText(dir / "m.nrrd"), "old");
    EXPECT_EQ(entries(dir), 1u);
}

// /dev/full fails every write with ENOSPC, the errno a full disk gives.
TEST(FileWrite, FullDiskSaysHowMuchWasNotWritten) {
    const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
        GTEST_SKIP() << "no /dev/full on this machine";
    }
    const std::vector<std::byte> bytes(1000);
    const std::string m = messageOf(
        [&] { files::writeAllTo(fd, "/exports/m.nii.gz", {std::span<const std::byte>(bytes)}); });
    ::close(fd);
    EXPECT_EQ(m, "/exports/m.nii.gz: the disk is full: 1000 bytes could not be written to "
                 "/exports");
}

// The whole path failing halfway: a child process may write files of at most 4 KiB, so the
// write loop fails (EFBIG) after the first 4 KiB of the temporary file. The child reports the
// message on a pipe; the parent checks the folder afterwards.
TEST(FileWrite, FailureHalfwayLeavesTheOldFileAndNoTemporary) {
    const auto dir = tempDir("write-limit");
    const auto target = dir / "mask.nrrd";
    writeText(target, "the previous export");
    int pipeFds[2];
    ASSERT_EQ(::pipe(pipeFds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(pipeFds[0]);
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        const std::vector<std::byte> big(64 * 1024, std::byte{7});
        const std::string m = messageOf(
            [&] { files::writeFileAtomically(target, {std::span<const std::byte>(big)}); });
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
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    EXPECT_EQ(m, target.string() +
                     ": the file is larger than this system lets the program "
                     "write: " +
                     std::to_string(64 * 1024 - 4096) + " bytes could not be written to " +
                     dir.string());
    EXPECT_EQ(readText(target), "the previous export");
    EXPECT_EQ(entries(dir), 1u);
}

} // namespace
} // namespace steerseg::test
