// [dicom] keep_days: series whose newest file is older go, a series still arriving stays, and
// study folders left empty go with them.
#include "net/store_retention.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

void file(const fs::path& path, fs::file_time_type when) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "x";
    fs::last_write_time(path, when);
}

TEST(NetRetention, OldSeriesGoNewAndArrivingOnesStay) {
    const fs::path store = tempDir("net-retention");
    const auto now = fs::file_time_type::clock::now();
    file(store / "1.1" / "1.1.1" / "a.dcm", now - 200h);
    file(store / "1.1" / "1.1.2" / "a.dcm", now - 200h);
    file(store / "1.1" / "1.1.2" / "b.dcm", now - 1h); // still arriving
    file(store / "1.2" / "1.2.1" / "a.dcm", now - 170h);
    file(store / "1.3" / "1.3.1" / "a.dcm", now);
    fs::last_write_time(store / "1.1" / "1.1.1", now - 200h);
    fs::last_write_time(store / "1.2" / "1.2.1", now - 170h);

    EXPECT_EQ(net::pruneStore(store, 168h, now), 2);
    EXPECT_FALSE(fs::exists(store / "1.1" / "1.1.1"));
    EXPECT_TRUE(fs::exists(store / "1.1" / "1.1.2" / "a.dcm"));
    EXPECT_FALSE(fs::exists(store / "1.2")); // its only series went
    EXPECT_TRUE(fs::exists(store / "1.3" / "1.3.1" / "a.dcm"));
    EXPECT_EQ(net::pruneStore(store, 168h, now), 0);
    EXPECT_EQ(net::pruneStore(store / "missing", 168h, now), 0);
    fs::remove_all(store);
}

} // namespace
} // namespace steerseg::test
