// `steerseg listen` as the scanner sees it: DCMTK's storescu pushes a real CT series, echoscu
// asks whether the node answers, and callers it does not know, associations past their quota
// and bytes that are no DICOM at all are turned away while the node keeps serving.
#include "net/net_harness.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;

// The scanner's side: a real CT series and DCMTK's storescu and echoscu.
class NetListen : public ::testing::Test {
  protected:
    void SetUp() override {
        STEERSEG_REQUIRE_PROGRAM("/usr/bin/storescu", "dcmtk");
        STEERSEG_REQUIRE_PROGRAM("/usr/bin/echoscu", "dcmtk");
        const auto found = dataPath("lung-ct-ibsi/dicom/image");
        if (!found) {
            STEERSEG_SKIP_OR_FAIL_FOR_DATA("lung-ct-ibsi/dicom/image");
        }
        series = *found;
    }
    fs::path series;
};

TEST_F(NetListen, StoresAScannersSeriesAndAnswersEcho) {
    const fs::path dir = tempDir("net-listen-series");
    ListenProcess node(dir, {"--allow", "SCANNER", "--allow", "PACS@127.0.0.1"});

    const Finished echo = node.echo("SCANNER");
    EXPECT_EQ(echo.status, 0) << echo.output;

    const Finished pushed = node.storescu("SCANNER", series);
    ASSERT_EQ(pushed.status, 0) << pushed.output << node.log();
    const std::size_t sent = static_cast<std::size_t>(
        std::distance(fs::directory_iterator(series), fs::directory_iterator{}));
    const std::vector<fs::path> stored = filesBelow(dir / "store");
    EXPECT_EQ(stored.size(), sent) << node.log();
    for (const fs::path& f : stored) {
        // <store>/<study>/<series>/<instance>.dcm: one study, one series.
        EXPECT_EQ(f.extension(), ".dcm");
        EXPECT_EQ(f.parent_path().parent_path().parent_path(), dir / "store") << f;
        EXPECT_EQ(f.parent_path(), stored.front().parent_path()) << f;
    }

    // An object larger than one encoding pass (1 MiB) arrives whole: a CT slice given 3 MiB of
    // pixels (1024 x 1536 x 16 bit) of a known pattern.
    DcmFileFormat big;
    ASSERT_TRUE(big.loadFile((series / "DCM_IMG_00003.dcm").c_str()).good());
    DcmDataset& data = *big.getDataset();
    std::vector<Uint16> pixels(1024u * 1536u);
    for (std::size_t n = 0; n < pixels.size(); ++n) {
        pixels[n] = static_cast<Uint16>(n * 2654435761u >> 16);
    }
    data.putAndInsertUint16(DCM_Rows, 1536);
    data.putAndInsertUint16(DCM_Columns, 1024);
    data.putAndInsertUint16Array(DCM_PixelData, pixels.data(), pixels.size());
    data.putAndInsertString(DCM_SOPInstanceUID, "1.2.826.0.1.3680043.10.1234.24.1");
    ASSERT_TRUE(big.saveFile((dir / "big.dcm").c_str(), EXS_LittleEndianExplicit).good());
    const Finished bigPush = node.storescu("SCANNER", dir / "big.dcm");
    ASSERT_EQ(bigPush.status, 0) << bigPush.output << node.log();
    DcmFileFormat received;
    const fs::path bigPath = stored.front().parent_path() / "1.2.826.0.1.3680043.10.1234.24.1.dcm";
    ASSERT_TRUE(received.loadFile(bigPath.c_str()).good()) << node.log();
    const Uint16* back = nullptr;
    unsigned long count = 0;
    ASSERT_TRUE(received.getDataset()->findAndGetUint16Array(DCM_PixelData, back, &count).good());
    ASSERT_EQ(count, pixels.size());
    EXPECT_TRUE(std::equal(pixels.begin(), pixels.end(), back));
    // An address-bound caller from its address is let in too.
    EXPECT_EQ(node.echo("PACS").status, 0);

    const Finished intruder = node.storescu("INTRUDER", series / "DCM_IMG_00000.dcm");
    EXPECT_NE(intruder.status, 0) << intruder.output;
    EXPECT_NE(node.log().find("rejected association from INTRUDER at 127.0.0.1: calling AE "
                              "title not allowed"),
              std::string::npos)
        << node.log();
    EXPECT_EQ(filesBelow(dir / "store").size(), sent + 1);

    EXPECT_EQ(node.process->stop(), 0);
    EXPECT_NE(node.log().find("stopped"), std::string::npos) << node.log();
    fs::remove_all(dir);
}

TEST_F(NetListen, QuotaAndGarbageAreRefusedAndTheNodeKeepsServing) {
    const fs::path dir = tempDir("net-listen-quota");
    // The series is about 5 MB: a 1 MiB quota stops the association within its first objects.
    ListenProcess node(dir, {"--allow", "SCANNER", "--quota-mb", "1"});

    const Finished pushed = node.storescu("SCANNER", series);
    EXPECT_NE(pushed.status, 0) << pushed.output;
    // storescu may see the abort before the node has written its line.
    EXPECT_TRUE(waitUntil(
        [&] {
            return node.log().find("aborted association from SCANNER: more than 1 MiB") !=
                   std::string::npos;
        },
        std::chrono::seconds(5)))
        << node.log();
    const std::vector<fs::path> stored = filesBelow(dir / "store");
    EXPECT_LT(stored.size(), 20u);
    std::size_t marks = 0;
    for (const fs::path& f : stored) {
        // The one hidden file allowed: the mark that says the series is incomplete.
        if (f.filename().string().rfind(".receiving-", 0) == 0) {
            ++marks;
            continue;
        }
        EXPECT_NE(f.filename().string().front(), '.') << "a half-written file is left: " << f;
    }
    EXPECT_EQ(marks, stored.empty() ? 0U : 1U);

    // Bytes that are no PDU at all, then a connection dropped half-way through a PDU header.
    for (const std::string& junk : {std::string(4096, '\x5a'), std::string("\x01\x00\x00", 3)}) {
        const int fd = connectLoopback(node.port);
        ASSERT_GE(fd, 0);
        ::send(fd, junk.data(), junk.size(), MSG_NOSIGNAL);
        ::close(fd);
    }
    const Finished echo = node.echo("SCANNER");
    EXPECT_EQ(echo.status, 0) << echo.output << node.log();
    EXPECT_TRUE(node.process->running());
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

// A store whose disk would keep less than min_free_mb: every object is refused with 0xA700 (out
// of resources), nothing lands in the store, and an AE allowed only from elsewhere is turned
// away.
TEST_F(NetListen, AFullStoreRefusesEachObjectAndKeepsNothing) {
    const fs::path dir = tempDir("net-listen-full");
    std::ofstream(dir / "node.toml")
        << "[dicom]\nmin_free_mb = 1048576\n"
           "[[dicom.peers]]\nname = \"ct\"\naet = \"SCANNER\"\n"
           "host = \"ct\"\nreceive = true\n"
           "[[dicom.peers]]\nname = \"pacs\"\naet = \"PACS\"\n"
           "host = \"pacs\"\naddress = \"192.0.2.7\"\nreceive = true\n";
    ListenProcess node(dir, {"--config", (dir / "node.toml").string()});
    const Finished pushed = node.storescu("SCANNER", series / "DCM_IMG_00000.dcm");
    EXPECT_NE(pushed.status, 0) << pushed.output;
    EXPECT_NE(node.log().find("refused object from SCANNER: the store has"), std::string::npos)
        << node.log();
    EXPECT_TRUE(filesBelow(dir / "store").empty());
    const Finished elsewhere = node.echo("PACS");
    EXPECT_NE(elsewhere.status, 0) << elsewhere.output;
    EXPECT_NE(node.log().find("rejected association from PACS at 127.0.0.1: calling AE title not "
                              "allowed from this address"),
              std::string::npos)
        << node.log();
    EXPECT_EQ(node.process->stop(), 0);
    fs::remove_all(dir);
}

TEST(NetListenOptions, RefusesAStartItCannotServe) {
    const fs::path dir = tempDir("net-listen-usage");
    const Finished nobody =
        runProgram({steersegBinary().string(), "listen", "--store", dir.string()}, dir);
    EXPECT_EQ(nobody.status, 2);
    EXPECT_NE(nobody.output.find("nobody may send"), std::string::npos) << nobody.output;
    const Finished badAe = runProgram({steersegBinary().string(), "listen", "--store", dir.string(),
                                       "--allow", "WAY-TOO-LONG-FOR-AN-AE-TITLE"},
                                      dir);
    EXPECT_EQ(badAe.status, 2);
    EXPECT_NE(badAe.output.find("1 to 16 characters"), std::string::npos) << badAe.output;
    fs::remove_all(dir);
}

} // namespace
} // namespace steerseg::test
