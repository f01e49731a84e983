// `steerseg measure` end to end: its JSON on NIfTI files written here, a label map's label, the
// table, and its refusals, each one line on stderr with its exit status. With the real data, the
// lung-ct-ibsi GTV's volume.
#include "support/cli_run.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace steerseg::test {
namespace {

long lineCount(const std::string& text) {
    return std::count(text.begin(), text.end(), '\n');
}

class CliMeasure : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = tempDir("cli-measure");
        grid.dims = {20, 18, 8};
        grid.spacing = {0.7, 0.9, 2.5};
        grid.origin = {-10.0, 20.0, 30.0};
        // The scan: int16 HU-like values i + 10 j; the label map: 1 a block, 2 one voxel.
        std::vector<double> scan(grid.voxelCount());
        std::vector<double> labels(grid.voxelCount(), 0.0);
        for (int k = 0; k < grid.dims.z; ++k) {
            for (int j = 0; j < grid.dims.y; ++j) {
                for (int i = 0; i < grid.dims.x; ++i) {
                    const std::size_t n = linearIndex(grid.dims, i, j, k);
                    scan[n] = i + 10.0 * j - 100.0;
                    if (i >= 3 && i < 13 && j >= 4 && j < 10 && k >= 2 && k < 5) {
                        labels[n] = 1.0;
                    }
                }
            }
        }
        labels[linearIndex(grid.dims, 17, 15, 6)] = 2.0;
        NiftiOptions int16;
        int16.datatype = 4; // NIFTI_TYPE_INT16
        writeFile(dir / "scan.nii", niftiFile(grid, encodeSamples(scan, "int16"), int16));
        writeFile(dir / "labels.nii", niftiFile(grid, encodeSamples(labels, "uint8")));
        Geometry other = grid;
        other.dims.z = 7;
        writeFile(
            dir / "other.nii",
            niftiFile(other, encodeSamples(std::vector<double>(other.voxelCount(), 1.0), "uint8")));
    }
    CliRun measure(const std::string& more) {
        return runSteerseg("measure --input " + (dir / "scan.nii").string() + " " + more);
    }
    std::filesystem::path dir;
    Geometry grid;
};

TEST_F(CliMeasure, JsonOfALabel) {
    const CliRun r = measure("--mask " + (dir / "labels.nii").string() + " --label 1 --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["label"], 1);
    EXPECT_EQ(j["voxels"], 10 * 6 * 3);
    EXPECT_NEAR(j["volume_ml"].get<double>(), 180 * 0.7 * 0.9 * 2.5 / 1000.0,
                1e-6); // a NIfTI header holds the spacing as float
    EXPECT_GT(j["surface_area_mm2"].get<double>(), 0.0);
    EXPECT_EQ(j["axial"]["slice_axis"], "k");
    EXPECT_EQ(j["axial"]["slice"], 2);
    EXPECT_NEAR(j["axial"]["longest"]["length_mm"].get<double>(), std::hypot(9 * 0.7, 5 * 0.9),
                1e-5);
    EXPECT_NEAR(j["longest_3d"]["length_mm"].get<double>(),
                glm::length(glm::dvec3(9 * 0.7, 5 * 0.9, 2 * 2.5)), 1e-5);
    const auto from = j["axial"]["longest"]["from"];
    EXPECT_EQ(from["index"].size(), 3u);
    EXPECT_EQ(from["lps_mm"].size(), 3u);
    // i + 10 j - 100 over i 3..12, j 4..9: mean 7.5 + 65 - 100, min 3 + 40 - 100, max 12 + 90 -
    // 100.
    EXPECT_DOUBLE_EQ(j["intensity"]["mean"].get<double>(), -27.5);
    EXPECT_DOUBLE_EQ(j["intensity"]["min"].get<double>(), -57.0);
    EXPECT_DOUBLE_EQ(j["intensity"]["max"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(j["intensity"]["sd"].get<double>(), std::sqrt(8.25 + 100.0 * 35.0 / 12.0));

    // Non-zero by default: the block and the stray voxel of label 2.
    const CliRun all = measure("--mask " + (dir / "labels.nii").string() + " --json");
    ASSERT_EQ(all.exitCode, 0) << all.err;
    EXPECT_EQ(nlohmann::json::parse(all.out)["voxels"], 181);
}

TEST_F(CliMeasure, TableForPeople) {
    const CliRun r = measure("--mask " + (dir / "labels.nii").string() + " --label 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* row : {"volume ", "surface area ", "longest axial ", "perpendicular ",
                            "longest 3D ", "intensity mean "}) {
        EXPECT_NE(r.out.find(row), std::string::npos) << row << " in:\n" << r.out;
    }
}

TEST_F(CliMeasure, BadInputIsOneLineAndItsStatus) {
    struct Case {
        std::string options;
        int status;
        std::string says;
    };
    const std::string labels = (dir / "labels.nii").string();
    const std::vector<Case> cases{
        {"--mask " + labels + " --label 7", 2, "--label 7: no voxel of " + labels},
        {"--mask " + labels + " --label one", 2, "--label: expected an integer, got 'one'"},
        {"--mask " + (dir / "other.nii").string(), 2, "the mask is 20x18x7 voxels"},
        {"", 2, "--mask"},
        {"--mask " + (dir / "missing.nii").string(), 1, "missing.nii"},
    };
    for (const Case& c : cases) {
        const CliRun r = measure(c.options);
        EXPECT_EQ(r.exitCode, c.status) << c.options << ": " << r.err;
        EXPECT_TRUE(r.out.empty()) << c.options;
        const std::string first = r.err.substr(0, r.err.find('\n'));
        EXPECT_EQ(first.rfind("steerseg measure: ", 0), 0u) << r.err;
        EXPECT_NE(first.find(c.says), std::string::npos) << c.options << ": " << r.err;
        // A usage error adds the command's usage line; nothing else.
        EXPECT_EQ(lineCount(r.err), c.status == 2 ? 2 : 1) << r.err;
    }
}

// With ITK-SNAP's label description beside the label map (as the exports write it): the label's
// name in the table and the JSON; a label the description does not name, in the map or asked
// for, and a garbled description, refused in one line before anything is measured.
TEST_F(CliMeasure, TheLabelDescriptionNamesEveryLabel) {
    const std::string labels = (dir / "labels.nii").string();
    const auto describe = [&](const std::string& rows) {
        writeFile(dir / "labels.label.txt",
                  "# ITK-SnAP Label Description File\n"
                  "    0     0    0    0        0  0  0    \"Clear Label\"\n" +
                      rows);
    };
    describe("    1   255    0    0        1  1  1    \"Liver\"\n"
             "    2     0    0  255        1  1  1    \"Spleen (accessory)\"\n");
    const CliRun json = measure("--mask " + labels + " --label 2 --json");
    ASSERT_EQ(json.exitCode, 0) << json.err;
    EXPECT_EQ(nlohmann::json::parse(json.out)["name"], "Spleen (accessory)");
    const CliRun table = measure("--mask " + labels + " --label 1");
    ASSERT_EQ(table.exitCode, 0) << table.err;
    EXPECT_NE(table.out.find("structure             Liver\n"), std::string::npos) << table.out;

    describe("    1   255    0    0        1  1  1    \"Liver\"\n");
    for (const std::string& options : {std::string(""), std::string(" --label 1")}) {
        const CliRun r = measure("--mask " + labels + options);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_TRUE(r.out.empty());
        EXPECT_NE(r.err.find("holds label 2, which labels.label.txt beside it does not name (it "
                             "names 1 Liver)"),
                  std::string::npos)
            << r.err;
    }
    describe("    1   255    0    0        1  1  1    \"Liver\"\n"
             "    2     0    0  255        1  1  1    \"Spleen\"\n"
             "    3     0  255    0        1  1  1    \"Kidney\"\n");
    const CliRun notThere = measure("--mask " + labels + " --label 3");
    EXPECT_EQ(notThere.exitCode, 2);
    EXPECT_NE(notThere.err.find("--label 3: no voxel of"), std::string::npos) << notThere.err;
    describe("    2     0    0  255        1  1  1    \"Spleen\"\n");
    const CliRun unnamed = measure("--mask " + labels + " --label 1");
    EXPECT_EQ(unnamed.exitCode, 2);
    EXPECT_NE(unnamed.err.find("holds label 1"), std::string::npos) << unnamed.err;

    for (const std::string& garbled :
         {std::string("    1   255    0 \"Liver\"\n"), std::string("    1 255 0 0 1 1 1 Liver\n"),
          std::string("    0 0 0 0 0 0 0 \"Again\"\n")}) {
        describe(garbled);
        const CliRun r = measure("--mask " + labels + " --label 1");
        EXPECT_EQ(r.exitCode, 2) << garbled << r.err;
        EXPECT_NE(r.err.find("labels.label.txt line 3: "), std::string::npos) << r.err;
        EXPECT_EQ(lineCount(r.err), 2) << r.err;
    }
}

// The lung-ct-ibsi GTV: its volume is its voxel count times the voxel's volume, exactly.
TEST(CliMeasureRealData, LungGtvVolumeIsItsVoxels) {
    STEERSEG_REQUIRE_DATA(image, "lung-ct-ibsi/nifti/image.nii.gz");
    STEERSEG_REQUIRE_DATA(mask, "lung-ct-ibsi/nifti/mask.nii.gz");
    const CliRun r =
        runSteerseg("measure --input " + image.string() + " --mask " + mask.string() + " --json");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const CliRun info = runSteerseg("info " + image.string());
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const auto spacing = nlohmann::json::parse(info.out)["spacing"];
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["voxels"], 125256); // SOURCES.md
    EXPECT_EQ(j["volume_ml"].get<double>(),
              125256.0 *
                  (spacing[0].get<double>() * spacing[1].get<double>() * spacing[2].get<double>()) /
                  1000.0);
    EXPECT_GT(j["axial"]["longest"]["length_mm"].get<double>(),
              j["axial"]["perpendicular"]["length_mm"].get<double>());
    EXPECT_LT(j["intensity"]["min"].get<double>(), j["intensity"]["mean"].get<double>());
}

} // namespace
} // namespace steerseg::test
