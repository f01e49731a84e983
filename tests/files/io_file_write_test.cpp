// files::writeFileAtomically's failures, each caused for real: a missing folder, a read-only one
// (not deniable as root), a full disk through /dev/full at the write loop's seam, and a file
// size limit (RLIMIT_FSIZE in a forked child: write() fails with EFBIG) through the whole path.
// After every failure no temporary file is left and an existing file is unchanged.
#include "files/file_write.hpp"
#include "scan/scan_reader.hpp"
#include "support/test_data.hpp"
#include "support/unprivileged.hpp"
#include "support/write_faults.hpp"

#include <fcntl.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

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
    EXPECT_EQ(entryCount(dir), 1u);
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
    const std::string m = writeErrorOf([&] { writeText(folder / "m.nrrd", "x"); });
    EXPECT_NE(m.find("the folder " + folder.string() + " does not exist"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(FileWrite, AFolderInTheWayIsNamed) {
    const auto dir = tempDir("write-folder");
    std::filesystem::create_directory(dir / "m.nrrd");
    const std::string m = writeErrorOf([&] { writeText(dir / "m.nrrd", "x"); });
    EXPECT_NE(m.find("a folder of that name is in the way"), std::string::npos) << m;
    EXPECT_EQ(entryCount(dir), 1u);
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
        runUnprivileged([&] { return writeErrorOf([&] { writeText(dir / "m.nrrd", "new"); }); });
    std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
    EXPECT_NE(m.find("the folder " + dir.string() + " is not writable"), std::string::npos) << m;
    EXPECT_EQ(readText(dir / "m.nrrd"), "old");
    EXPECT_EQ(entryCount(dir), 1u);
}

// /dev/full fails every write with ENOSPC, the errno a full disk gives.
TEST(FileWrite, FullDiskSaysHowMuchWasNotWritten) {
    const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
    if (fd < 0) {
        GTEST_SKIP() << "no /dev/full on this machine";
    }
    const std::vector<std::byte> bytes(1000);
    const std::string m = writeErrorOf(
        [&] { files::writeAllTo(fd, "/exports/m.nii.gz", {std::span<const std::byte>(bytes)}); });
    ::close(fd);
    EXPECT_EQ(m, "/exports/m.nii.gz: the disk is full: 1000 bytes could not be written to "
                 "/exports");
}

// The whole path failing halfway: a child process may write files of at most 4 KiB, so the
// write loop fails (EFBIG) after the first 4 KiB of the temporary file. The child reports the
// message; the parent checks the folder afterwards.
TEST(FileWrite, FailureHalfwayLeavesTheOldFileAndNoTemporary) {
    const auto dir = tempDir("write-limit");
    const auto target = dir / "mask.nrrd";
    writeText(target, "the previous export");
    const std::vector<std::byte> big(64 * 1024, std::byte{7});
    const std::string m = writeErrorUnderSizeLimit(
        [&] { files::writeFileAtomically(target, {std::span<const std::byte>(big)}); }, 4096);
    EXPECT_EQ(m, target.string() +
                     ": the file is larger than this system lets the program "
                     "write: " +
                     std::to_string(64 * 1024 - 4096) + " bytes could not be written to " +
                     dir.string());
    EXPECT_EQ(readText(target), "the previous export");
    EXPECT_EQ(entryCount(dir), 1u);
}

} // namespace
} // namespace steerseg::test
