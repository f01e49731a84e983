// The light build's modules (STEERSEG_LIGHT, the GPU pack's kiosk), compiled here into the full
// build's test so they cannot rot between GPU sessions: each part the light build leaves out
// refuses with one line naming the light build and the library it would need, through the same
// entry points the kiosk and the command line call (the scan dispatcher, the exports, the
// kiosk's DICOM node, the self-test, the commands, the displays).
#include "cli/commands.hpp"
#include "cli/self_test_dicom.hpp"
#include "exports/dicom_seg_writer.hpp"
#include "exports/image_file.hpp"
#include "exports/tiff_writer.hpp"
#include "files/file_error.hpp"
#include "kiosk/kiosk_dicom_node.hpp"
#include "platform/kms/kms_display.hpp"
#include "platform/window/window_display.hpp"
#include "scan/scan_reader.hpp"
#include "workflow/audit_log.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace {

namespace fs = std::filesystem;

fs::path tempFolder(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / ("light-build-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

template <typename Error, typename F> std::string messageOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "nothing thrown";
    return "";
}

void expectLightLine(const std::string& message, const std::string& library) {
    EXPECT_NE(message.find("not in this light build of steerseg (STEERSEG_LIGHT"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("needs " + library), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(LightBuild, ScanDispatcherRefusesDicomAndPictures) {
    const fs::path dir = tempFolder("scans");
    std::ofstream(dir / "slice.dcm") << std::string(128, '\0') << "DICM";
    std::ofstream(dir / "photo.png") << "not read";
    const std::string dicom =
        messageOf<steerseg::scan::ScanError>([&] { steerseg::scan::readScan(dir / "slice.dcm"); });
    expectLightLine(dicom, "GDCM");
    EXPECT_NE(dicom.find("slice.dcm: Reading DICOM"), std::string::npos) << dicom;
    // A folder holding DICOM goes the same way.
    expectLightLine(messageOf<steerseg::scan::ScanError>([&] { steerseg::scan::readScan(dir); }),
                    "GDCM");
    expectLightLine(
        messageOf<steerseg::scan::ScanError>([&] { steerseg::scan::readScan(dir / "photo.png"); }),
        "OpenImageIO");
    // What it does read is the full build's own.
    EXPECT_EQ(steerseg::scan::readScan("builtin:sample").format, "builtin");
}

TEST(LightBuild, ExportsWritePngAndRefuseTiffAndDicomSeg) {
    const fs::path dir = tempFolder("exports");
    const steerseg::RgbaImage picture{2, 1, {1, 2, 3, 255, 4, 5, 6, 255}};
    steerseg::exports::writeImage(dir / "frame.png", picture);
    std::ifstream png(dir / "frame.png", std::ios::binary);
    std::string signature(8, '\0');
    png.read(signature.data(), 8);
    EXPECT_EQ(signature, "\x89PNG\r\n\x1a\n");
    expectLightLine(messageOf<steerseg::files::WriteError>(
                        [&] { steerseg::exports::writeImage(dir / "frame.tif", picture); }),
                    "OpenImageIO");
    EXPECT_FALSE(fs::exists(dir / "frame.tif"));
    expectLightLine(
        messageOf<std::runtime_error>([&] { steerseg::exports::readImage(dir / "frame.png"); }),
        "OpenImageIO");

    const steerseg::Geometry geometry{};
    const std::vector<std::uint8_t> mask(1, 1);
    expectLightLine(messageOf<steerseg::files::WriteError>([&] {
                        steerseg::exports::writeTiffStack(dir / "mask.tif", geometry, mask);
                    }),
                    "OpenImageIO");
    expectLightLine(messageOf<steerseg::files::WriteError>([&] {
                        steerseg::exports::writeDicomSeg(dir / "seg.dcm", geometry, mask, nullptr);
                    }),
                    "DCMTK");
}

TEST(LightBuild, KioskDicomNodeSaysSoOnceAndShowsNothing) {
    const fs::path dir = tempFolder("node");
    steerseg::workflow::AuditLog audit(dir / "audit.log");
    steerseg::config::DicomConfig on;
    on.enabled = true;
    steerseg::kiosk::DicomNode node(on);
    steerseg::workflow::Status status;
    status.outbox = {"left from before"};
    std::ostringstream err;
    node.frame(status, audit, err);
    EXPECT_NE(err.str().find("steerseg kiosk: dicom: The DICOM node ([dicom] enabled = "
                             "true) is not in this light build"),
              std::string::npos)
        << err.str();
    EXPECT_NE(err.str().find("needs DCMTK"), std::string::npos) << err.str();
    const std::string first = err.str();
    node.frame(status, audit, err);
    node.finish(audit, err);
    EXPECT_EQ(err.str(), first); // once, not every frame
    EXPECT_TRUE(node.shown(status).outbox.empty());

    std::ostringstream quiet;
    steerseg::kiosk::DicomNode off(steerseg::config::DicomConfig{});
    off.frame(status, audit, quiet);
    off.finish(audit, quiet);
    EXPECT_EQ(quiet.str(), "");
}

TEST(LightBuild, SelfTestFailsOnlyAConfiguredNode) {
    steerseg::config::DicomConfig dicom;
    auto off = steerseg::cli::checkDicomNode(dicom);
    ASSERT_EQ(off.size(), 1u);
    EXPECT_EQ(off[0].level, steerseg::cli::CheckLevel::Ok);
    dicom.enabled = true;
    auto on = steerseg::cli::checkDicomNode(dicom);
    ASSERT_EQ(on.size(), 1u);
    EXPECT_EQ(on[0].level, steerseg::cli::CheckLevel::Fail);
    expectLightLine(on[0].detail, "DCMTK");
}

TEST(LightBuild, DicomCommandsRefuseByName) {
    const std::vector<std::string> args = {"--to", "PACS", "seg.dcm"};
    for (const auto& [name, run] : {std::pair{"send", &steerseg::cli::runSend},
                                    std::pair{"listen", &steerseg::cli::runListen},
                                    std::pair{"export", &steerseg::cli::runExport}}) {
        const std::string message = messageOf<std::runtime_error>([&] { run(args); });
        expectLightLine(message, "DCMTK");
        EXPECT_NE(message.find(std::string("'") + name + "'"), std::string::npos) << message;
    }
}

TEST(LightBuild, WindowAndKmsDisplaysPointToOffscreen) {
    const steerseg::platform::DisplayOptions options;
    for (const std::string& message : {messageOf<steerseg::platform::DisplayError>(
                                           [&] { steerseg::platform::openWindowDisplay(options); }),
                                       messageOf<steerseg::platform::DisplayError>(
                                           [&] { steerseg::platform::openKmsDisplay(options); })}) {
        EXPECT_NE(message.find("not in this light build of steerseg (STEERSEG_LIGHT"),
                  std::string::npos)
            << message;
        EXPECT_NE(message.find("use --platform offscreen"), std::string::npos) << message;
    }
}

} // namespace
