#include "workflow/utc_time.hpp"
#include "support/workflow_rig.hpp"

#include <filesystem>
#include <gtest/gtest.h>

namespace steerseg::test {
namespace {

using namespace workflow;

using namespace model;
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / name;
    fs::remove_all(dir);
    return dir;
}

TEST(WorkflowExport, UtcStampsIgnoreTheLocalZone) {
    EXPECT_EQ(isoUtc(fixedTime()), "2026-11-23T13:01:40.000Z");
    EXPECT_EQ(isoUtc(fixedTime() + std::chrono::milliseconds(1234)), "2026-11-23T13:01:41.234Z");
    EXPECT_EQ(compactUtc(fixedTime()), "20261123-130140");
}

TEST(WorkflowExport, DefaultNameFromScanAndTimeInACreatedFolder) {
    Settings s = testSettings();
    s.exportFolder = freshDir("workflow-export-default") / "nested";
    Rig rig(s);
    rig.engine.writeExports = true;
    rig.driveTo(State::Review);
    ASSERT_TRUE(rig.act(Proceed{}).accepted);
    EXPECT_EQ(rig.state(), State::Done);
    const fs::path expected = s.exportFolder / "fake_20261123-130140.nii.gz";
    EXPECT_EQ(rig.status().exportedPath, expected.string());
    ASSERT_EQ(rig.engine.exports.size(), 1U);
    EXPECT_EQ(rig.engine.exports[0], expected);
    EXPECT_TRUE(fs::exists(expected));
    EXPECT_NE(rig.status().message.find(expected.string()), std::string::npos);
    // A second export in the same second does not overwrite the first.
    ASSERT_TRUE(rig.act(Back{}).accepted);
    ASSERT_TRUE(rig.act(Export{}).accepted);
    EXPECT_EQ(rig.status().exportedPath,
              (s.exportFolder / "fake_20261123-130140-2.nii.gz").string());
}

TEST(WorkflowExport, ADefaultExportWritesEveryConfiguredFormat) {
    Settings s = testSettings();
    s.exportFolder = freshDir("workflow-export-formats");
    s.exportFormats = {"nrrd", "nii.gz"};
    Rig rig(s);
    rig.engine.writeExports = true;
    rig.driveTo(State::Review);
    ASSERT_TRUE(rig.act(Export{}).accepted);
    ASSERT_EQ(rig.engine.exports.size(), 2U);
    EXPECT_EQ(rig.engine.exports[0], s.exportFolder / "fake_20261123-130140.nrrd");
    EXPECT_EQ(rig.engine.exports[1], s.exportFolder / "fake_20261123-130140.nii.gz");
    EXPECT_EQ(rig.status().exportedPath, rig.engine.exports[0].string());
    // The next name is free in every format, not just the first.
    ASSERT_TRUE(rig.act(Back{}).accepted);
    ASSERT_TRUE(rig.act(Export{}).accepted);
    EXPECT_EQ(rig.engine.exports[2], s.exportFolder / "fake_20261123-130140-2.nrrd");
    Settings bad = testSettings();
    bad.exportFormats = {};
    EXPECT_THROW(validateSettings(bad), std::invalid_argument);
    bad.exportFormats = {"../x"};
    EXPECT_THROW(validateSettings(bad), std::invalid_argument);
}

TEST(WorkflowExport, ScanNamesAreMadeFileSafe) {
    ScanInfo scan = FakeEngine::defaultScan();
    scan.name = "../Chest CT/séries";
    Settings s = testSettings();
    s.exportFolder = freshDir("workflow-export-names");
    Rig rig(s);
    rig.engine = FakeEngine(scan);
    rig.driveTo(State::Review);
    ASSERT_TRUE(rig.act(Export{}).accepted);
    const fs::path out = rig.status().exportedPath;
    EXPECT_EQ(out.parent_path(), s.exportFolder);
    EXPECT_EQ(out.filename().string().find('/'), std::string::npos);
    EXPECT_NE(out.filename().string()[0], '.');
}

TEST(WorkflowExport, FailureGoesBackToReviewWithTheWorkKept) {
    Rig rig;
    rig.driveTo(State::Review);
    rig.engine.exportError = "/mnt/usb/out.nii.gz: No space left on device";
    const Workflow::Outcome out = rig.act(Export{"/mnt/usb/out.nii.gz"});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(out.reason, "/mnt/usb/out.nii.gz: No space left on device");
    EXPECT_EQ(rig.state(), State::Review);
    EXPECT_EQ(rig.status().message, out.reason);
    EXPECT_TRUE(rig.status().hasLevelSet);
    EXPECT_FALSE(rig.act(LoadScan{"next.nii"}).accepted); // still unexported
    rig.engine.exportError.clear();
    ASSERT_TRUE(rig.act(Export{"/tmp/out.nii.gz"}).accepted);
    EXPECT_EQ(rig.status().exportedPath, "/tmp/out.nii.gz");
    EXPECT_TRUE(rig.act(LoadScan{"next.nii"}).accepted);
}

// One format failing (a full disk for the surface, say) leaves the others written, the work
// in review with the error shown, and a retry that writes every format.
TEST(WorkflowExport, OneFailingFormatKeepsTheOthersAndTheWork) {
    Settings s = testSettings();
    s.exportFolder = freshDir("workflow-export-partial");
    s.exportFormats = {"nrrd", "stl", "seg.nrrd"};
    Rig rig(s);
    rig.engine.writeExports = true;
    rig.engine.failExportsEndingIn = ".stl";
    rig.driveTo(State::Review);
    EXPECT_EQ(rig.status().exportFormats, s.exportFormats);
    const Workflow::Outcome out = rig.act(Export{});
    EXPECT_FALSE(out.accepted);
    EXPECT_EQ(rig.state(), State::Review);
    const fs::path base = s.exportFolder / "fake_20261123-130140";
    EXPECT_NE(out.reason.find(base.string() + ".stl: the disk is full"), std::string::npos)
        << out.reason;
    EXPECT_NE(out.reason.find("2 written"), std::string::npos) << out.reason;
    EXPECT_EQ(rig.status().message, out.reason);
    EXPECT_EQ(out.reason.find('\n'), std::string::npos);
    EXPECT_TRUE(fs::exists(base.string() + ".nrrd"));
    EXPECT_TRUE(fs::exists(base.string() + ".seg.nrrd"));
    EXPECT_FALSE(fs::exists(base.string() + ".stl"));
    EXPECT_TRUE(rig.status().hasLevelSet);
    EXPECT_FALSE(rig.act(LoadScan{"next.nii"}).accepted); // still unexported
    rig.engine.failExportsEndingIn.clear();
    ASSERT_TRUE(rig.act(Export{}).accepted);
    EXPECT_EQ(rig.state(), State::Done);
    // The retry takes a fresh name, since the first attempt's files exist.
    const fs::path again = s.exportFolder / "fake_20261123-130140-2";
    EXPECT_EQ(rig.status().exportedPath, again.string() + ".nrrd");
    EXPECT_TRUE(fs::exists(again.string() + ".stl"));
    EXPECT_TRUE(fs::exists(again.string() + ".seg.nrrd"));
    EXPECT_NE(rig.status().message.find("and 2 more"), std::string::npos) << rig.status().message;
}

TEST(WorkflowExport, AnUncreatableFolderIsAFailureNotACrash) {
    Settings s = testSettings();
    s.exportFolder = "/dev/null/exports";
    Rig rig(s);
    rig.driveTo(State::Review);
    const Workflow::Outcome out = rig.act(Export{});
    EXPECT_FALSE(out.accepted);
    EXPECT_NE(out.reason.find("/dev/null/exports"), std::string::npos) << out.reason;
    EXPECT_EQ(rig.state(), State::Review);
    EXPECT_TRUE(rig.engine.exports.empty());
}

} // namespace
} // namespace steerseg::test
