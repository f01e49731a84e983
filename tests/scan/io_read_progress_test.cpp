// A loader's progress: the bytes a scan read delivers are counted on the reading thread only.
#include "core/sample_phantom.hpp"
#include "exports/mask_writer.hpp"
#include "scan/read_progress.hpp"
#include "scan/scan_reader.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <thread>

namespace steerseg::test {
namespace {

TEST(ReadProgress, CountsTheFileBytesReadOnTheLoadingThreadOnly) {
    const auto path = std::filesystem::temp_directory_path() / "steerseg_read_progress.nii";
    const Geometry g = makeSamplePhantom().geometry();
    exports::writeMask(path, g, std::vector<std::uint8_t>(g.voxelCount(), 1));
    const std::uint64_t size = std::filesystem::file_size(path);

    std::atomic<std::uint64_t> counted{0};
    std::thread loader([&] {
        scan::countReadsInto(&counted);
        (void)scan::readScan(path);
        scan::countReadsInto(nullptr);
    });
    loader.join();
    // The voxels at least (the header may be read by nifticlib itself), never more than the file.
    EXPECT_GE(counted.load(), g.voxelCount());
    EXPECT_LE(counted.load(), size);

    const std::uint64_t before = counted.load();
    (void)scan::readScan(path); // this thread counts nothing
    EXPECT_EQ(counted.load(), before);
    std::filesystem::remove(path);
}

} // namespace
} // namespace steerseg::test
