// One rule turns a mask file into inside and outside (core/mask_inside.hpp): any non-zero value
// is inside. `steerseg export` of a mask labelled -1 or of a 0.4 probability map must give the
// voxels of the same 0/1 mask, not an empty export with exit 0; a NaN voxel is refused.
#include "core/mask_inside.hpp"
#include "exports/mask_writer.hpp"
#include "scan/scan_reader.hpp"
#include "support/cli_run.hpp"
#include "support/test_data.hpp"

#include <cmath>
#include <cstring>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>

namespace steerseg::test {
namespace {

const glm::ivec3 kDims{8, 7, 6};

Geometry grid() {
    Geometry g;
    g.dims = kDims;
    g.spacing = {1.0, 1.0, 1.0};
    return g;
}

// A box of voxels inside; the rest outside.
std::vector<std::uint8_t> boxMask() {
    std::vector<std::uint8_t> mask(grid().voxelCount());
    for (int k = 2; k < 5; ++k) {
        for (int j = 1; j < 4; ++j) {
            for (int i = 3; i < 7; ++i) {
                mask[linearIndex(kDims, i, j, k)] = 1;
            }
        }
    }
    return mask;
}

// The box's voxels as `inside` (float32 NRRD, LPS on the scan's grid), the rest 0.
void writeFloatMask(const std::filesystem::path& path, float inside) {
    const auto box = boxMask();
    std::vector<float> values(box.size());
    for (std::size_t n = 0; n < box.size(); ++n) {
        values[n] = box[n] != 0 ? inside : 0.0f;
    }
    std::ofstream out(path, std::ios::binary);
    out << "NRRD0004\ntype: float\ndimension: 3\nspace: left-posterior-superior\nsizes: " << kDims.x
        << " " << kDims.y << " " << kDims.z
        << "\nspace directions: (1,0,0) (0,1,0) (0,0,1)\nspace origin: (0,0,0)\n"
           "encoding: raw\nendian: little\n\n";
    out.write(reinterpret_cast<const char*>(values.data()),
              static_cast<std::streamsize>(values.size() * sizeof(float)));
}

struct Files {
    std::filesystem::path dir;
    std::filesystem::path scan;
};

Files makeScan(const std::string& name) {
    Files f{tempDir(name), {}};
    f.scan = f.dir / "scan.nii.gz";
    exports::writeMask(f.scan, grid(), std::vector<std::uint8_t>(grid().voxelCount(), 1));
    return f;
}

CliRun exportMask(const Files& f, const std::filesystem::path& mask, const std::string& out) {
    return runSteerseg("export --input " + f.scan.string() + " --mask " + mask.string() +
                       " --output " + (f.dir / out).string());
}

std::vector<std::uint8_t> exportedVoxels(const std::filesystem::path& path) {
    const Volume v = scan::readScan(path).volume;
    std::vector<std::uint8_t> inside(v.geometry().voxelCount());
    for (std::size_t n = 0; n < inside.size(); ++n) {
        inside[n] = v.storedAt(n) != 0 ? 1 : 0;
    }
    return inside;
}

TEST(FaultsMaskInside, ANegativeLabelAndAProbabilityMapExportAsTheZeroOneMask) {
    const Files f = makeScan("faults-mask-labels");
    exports::writeMask(f.dir / "binary.nii.gz", grid(), boxMask());
    writeFloatMask(f.dir / "minus.nrrd", -1.0f);
    writeFloatMask(f.dir / "prob.nrrd", 0.4f);
    for (const std::string name : {"binary.nii.gz", "minus.nrrd", "prob.nrrd"}) {
        SCOPED_TRACE(name);
        const CliRun r = exportMask(f, f.dir / name, "out-" + name + ".nrrd");
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(exportedVoxels(f.dir / ("out-" + name + ".nrrd")), boxMask());
    }
}

TEST(FaultsMaskInside, ANaNMaskIsRefusedInOneLine) {
    const Files f = makeScan("faults-mask-nan");
    writeFloatMask(f.dir / "nan.nrrd", std::numeric_limits<float>::quiet_NaN());
    const CliRun r = exportMask(f, f.dir / "nan.nrrd", "out.nrrd");
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("nan.nrrd"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("NaN"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(f.dir / "out.nrrd"));
}

TEST(FaultsMaskInside, TheRuleIsNonZeroAndRefusesNaN) {
    EXPECT_TRUE(insideValue(1.0));
    EXPECT_TRUE(insideValue(-1.0));
    EXPECT_TRUE(insideValue(0.4));
    EXPECT_FALSE(insideValue(0.0));
    EXPECT_THROW((void)insideValue(std::nan("")), std::invalid_argument);
}

} // namespace
} // namespace steerseg::test
