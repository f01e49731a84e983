// Several structures through exports::writeStructures, read back by other paths: label maps by
// steerseg's scan reader with their ITK-SNAP label descriptions, .seg.nrrd headers and (layered)
// voxels by zlib, meshes against each structure's own mesh; one structure as writeExport wrote
// it; and every refusal in one line, leaving no file.
#include "core/mask_field.hpp"
#include "core/surface_mesh.hpp"
#include "exports/mesh_writer.hpp"
#include "exports/structure_export.hpp"
#include "scan/scan_reader.hpp"
#include "structure_fixture.hpp"
#include "support/io_test_files.hpp"
#include "support/test_data.hpp"

#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <sstream>
#include <zlib.h>

namespace steerseg::test {

namespace fs = std::filesystem;

namespace {

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A NRRD's header, up to and with its blank line's first newline.
std::string nrrdHeaderOf(const fs::path& path) {
    const std::string text = fileText(path);
    return text.substr(0, text.find("\n\n") + 1);
}

// A gzip NRRD's voxels, inflated by zlib.
std::vector<std::uint8_t> nrrdVoxels(const fs::path& path) {
    const std::string text = fileText(path);
    const std::string packed = text.substr(text.find("\n\n") + 2);
    z_stream z{};
    EXPECT_EQ(inflateInit2(&z, 16 + MAX_WBITS), Z_OK);
    std::vector<std::uint8_t> out(1 << 20);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    z.avail_in = static_cast<uInt>(packed.size());
    z.next_out = out.data();
    z.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    inflateEnd(&z);
    return out;
}

bool hasLine(const std::string& text, const std::string& line) {
    return text.find("\n" + line + "\n") != std::string::npos;
}

struct Case {
    Geometry geometry = obliqueGeometry(kStructureDims);
    StructureMasks masks;
    std::vector<exports::StructureLayer> layers;
    explicit Case(bool overlapping)
        : masks(structureMasks(kStructureDims, overlapping)), layers(structureLayers(masks)) {}
    [[nodiscard]] exports::StructuresExport data() const { return {geometry, layers}; }
};

// Each voxel's label: the last structure holding it.
std::vector<std::uint8_t> expectedLabels(const Case& c) {
    std::vector<std::uint8_t> out(c.geometry.voxelCount(), 0);
    for (const exports::StructureLayer& s : c.layers) {
        for (std::size_t n = 0; n < out.size(); ++n) {
            out[n] = s.mask[n] != 0 ? static_cast<std::uint8_t>(s.segment.label) : out[n];
        }
    }
    return out;
}

} // namespace

TEST(StructureExport, LabelMapHoldsEachStructuresLabelAndNamesThemBeside) {
    for (const bool overlapping : {false, true}) {
        for (const char* name : {"organs.nii.gz", "organs.nii", "organs.nrrd"}) {
            SCOPED_TRACE(std::string(name) + (overlapping ? " overlapping" : ""));
            const Case c(overlapping);
            const fs::path dir = tempDir("structures-labels");
            const exports::ExportSummary s =
                exports::writeStructures(dir / name, *model::exportFormatOfFile(name), c.data());
            ASSERT_EQ(s.companions, std::vector<fs::path>{dir / "organs.label.txt"});
            const scan::LoadedScan back = scan::readScan(dir / name);
            expectSameGeometry(back.volume.geometry(), c.geometry, 1e-5);
            const std::vector<std::uint8_t> want = expectedLabels(c);
            const auto got = back.volume.voxels<std::uint8_t>();
            ASSERT_EQ(got.size(), want.size());
            EXPECT_TRUE(std::equal(got.begin(), got.end(), want.begin()));
            if (overlapping) {
                EXPECT_NE(s.note.find("voxels lie in more than one structure"), std::string::npos)
                    << s.note;
            } else {
                EXPECT_EQ(s.note, "");
            }
            // ITK-SNAP's rows: index, r g b 0..255, alpha, visible, mesh, the quoted name.
            std::istringstream rows(fileText(dir / "organs.label.txt"));
            std::vector<std::string> entries;
            bool header = false;
            for (std::string line; std::getline(rows, line);) {
                header = header || line.find("ITK-SnAP Label Description File") != line.npos;
                if (!line.empty() && line[0] != '#') {
                    std::istringstream w(line);
                    int idx = 0, r = 0, g = 0, b = 0, vis = 0, msh = 0;
                    double a = 0;
                    w >> idx >> r >> g >> b >> a >> vis >> msh;
                    std::string rest;
                    std::getline(w, rest);
                    entries.push_back(std::to_string(idx) + " " + std::to_string(r) + " " +
                                      std::to_string(g) + " " + std::to_string(b) + " " +
                                      std::to_string(static_cast<int>(a)) + " " +
                                      std::to_string(vis) + " " + std::to_string(msh) + rest);
                }
            }
            EXPECT_TRUE(header);
            EXPECT_EQ(entries, (std::vector<std::string>{"0 0 0 0 0 0 0    \"Clear Label\"",
                                                         "1 204 77 51 1 1 1    \"Liver\"",
                                                         "2 51 153 230 1 1 1    \"Spleen\"",
                                                         "3 255 217 26 1 1 1    \"Left kidney\""}));
            EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 2);
            fs::remove_all(dir);
        }
    }
}

TEST(StructureExport, SegNrrdOneLayerWhereNoneOverlap) {
    const Case c(false);
    const fs::path dir = tempDir("structures-segnrrd");
    const exports::ExportSummary s =
        exports::writeStructures(dir / "o.seg.nrrd", model::ExportFormat::SegNrrd, c.data());
    EXPECT_TRUE(s.companions.empty());
    const std::string h = nrrdHeaderOf(dir / "o.seg.nrrd");
    for (const char* line : {"dimension: 3",
                             "kinds: domain domain domain",
                             "Segment0_Name:=Liver",
                             "Segment0_ID:=Liver",
                             "Segment0_LabelValue:=1",
                             "Segment0_Layer:=0",
                             "Segment0_Color:=0.800000 0.300000 0.200000",
                             "Segment0_Extent:=2 9 2 15 1 6",
                             "Segment1_Name:=Spleen",
                             "Segment1_LabelValue:=2",
                             "Segment1_Layer:=0",
                             "Segment1_Extent:=13 19 3 9 1 7",
                             "Segment2_Name:=Left kidney",
                             "Segment2_ID:=Left kidney",
                             "Segment2_LabelValue:=3",
                             "Segment2_Layer:=0",
                             "Segment2_Color:=1.000000 0.850000 0.100000",
                             "Segment2_Extent:=13 21 12 17 5 8",
                             "Segment2_Tags:=Segmentation.Status:completed|",
                             "Segmentation_MasterRepresentation:=Binary labelmap",
                             "Segmentation_ReferenceImageExtentOffset:=0 0 0"}) {
        EXPECT_TRUE(hasLine(h, line)) << line << "\n" << h;
    }
    EXPECT_EQ(h.find("Segment3_"), std::string::npos);
    EXPECT_EQ(nrrdVoxels(dir / "o.seg.nrrd"), expectedLabels(c));
    fs::remove_all(dir);
}

// Slicer's layered form: the first axis a list of one layer per segment, a voxel's layers
// together, each layer its segment's label value inside.
TEST(StructureExport, SegNrrdOneLayerPerStructureWhereTheyOverlap) {
    const Case c(true);
    const fs::path dir = tempDir("structures-layers");
    exports::writeStructures(dir / "o.seg.nrrd", model::ExportFormat::SegNrrd, c.data());
    const std::string h = nrrdHeaderOf(dir / "o.seg.nrrd");
    for (const char* line :
         {"dimension: 4", "sizes: 3 24 20 10", "kinds: list domain domain domain",
          "Segment0_Layer:=0", "Segment1_Layer:=1", "Segment2_Layer:=2", "Segment0_LabelValue:=1",
          "Segment1_LabelValue:=2", "Segment2_LabelValue:=3", "Segment2_Extent:=13 21 8 17 3 8"}) {
        EXPECT_TRUE(hasLine(h, line)) << line << "\n" << h;
    }
    EXPECT_NE(h.find("\nspace directions: none ("), std::string::npos) << h;
    const std::vector<std::uint8_t> v = nrrdVoxels(dir / "o.seg.nrrd");
    ASSERT_EQ(v.size(), 3 * c.geometry.voxelCount());
    std::size_t shared = 0;
    for (std::size_t n = 0; n < c.geometry.voxelCount(); ++n) {
        int inside = 0;
        for (std::size_t l = 0; l < 3; ++l) {
            const exports::StructureLayer& s = c.layers[l];
            ASSERT_EQ(v[3 * n + l], s.mask[n] != 0 ? s.segment.label : 0) << n << " " << l;
            inside += s.mask[n] != 0 ? 1 : 0;
        }
        shared += inside > 1 ? 1 : 0;
    }
    EXPECT_GT(shared, 0U) << "the case should overlap";
    fs::remove_all(dir);
}

TEST(StructureExport, OneMeshPerStructure) {
    for (const auto format : {model::ExportFormat::Stl, model::ExportFormat::Ply}) {
        const Case c(true);
        const fs::path dir = tempDir("structures-mesh");
        const std::string ext = format == model::ExportFormat::Stl ? ".stl" : ".ply";
        const exports::ExportSummary s =
            exports::writeStructures(dir / ("organs" + ext), format, c.data());
        const std::vector<fs::path> files{dir / ("organs" + ext), dir / ("organs_2_Spleen" + ext),
                                          dir / ("organs_3_Left_kidney" + ext)};
        EXPECT_EQ(s.companions, std::vector<fs::path>(files.begin() + 1, files.end()));
        std::size_t triangles = 0;
        for (std::size_t n = 0; n < 3; ++n) {
            SCOPED_TRACE(files[n].string());
            const SurfaceMesh mesh =
                extractSurface(c.geometry, maskToField(c.geometry, c.layers[n].mask));
            triangles += mesh.triangles.size();
            const fs::path own = dir / "own" / files[n].filename();
            fs::create_directories(own.parent_path());
            exports::writeMesh(own, mesh,
                               format == model::ExportFormat::Stl ? exports::MeshFormat::Stl
                                                                  : exports::MeshFormat::Ply);
            ASSERT_TRUE(fs::exists(files[n]));
            EXPECT_EQ(fileText(files[n]), fileText(own));
        }
        EXPECT_EQ(s.triangles, triangles);
        fs::remove_all(dir);
    }
}

// One structure: every format writes what writeExport wrote before several existed.
TEST(StructureExport, OneStructureIsWhatTheSingleExportWrote) {
    const Case c(false);
    const fs::path dir = tempDir("structures-one");
    exports::StructuresExport one{c.geometry, {c.layers[1]}};
    for (const char* name : {"a.nii.gz", "a.nii", "a.nrrd"}) {
        const exports::ExportSummary s =
            exports::writeStructures(dir / name, *model::exportFormatOfFile(name), one);
        EXPECT_TRUE(s.companions.empty());
        exports::writeMask(dir / (std::string("m") + name), c.geometry, c.masks.spleen);
        EXPECT_EQ(fileText(dir / name), fileText(dir / (std::string("m") + name))) << name;
    }
    exports::writeStructures(dir / "a.seg.nrrd", model::ExportFormat::SegNrrd, one);
    exports::writeSegmentation(dir / "m.seg.nrrd", c.geometry, c.masks.spleen, c.layers[1].segment);
    EXPECT_EQ(fileText(dir / "a.seg.nrrd"), fileText(dir / "m.seg.nrrd"));
    const std::string h = nrrdHeaderOf(dir / "a.seg.nrrd");
    EXPECT_TRUE(hasLine(h, "dimension: 3")) << h;
    EXPECT_TRUE(hasLine(h, "Segment0_Name:=Spleen")) << h;
    const exports::ExportSummary stl =
        exports::writeStructures(dir / "a.stl", model::ExportFormat::Stl, one);
    EXPECT_TRUE(stl.companions.empty());
    exports::writeMesh(dir / "m.stl",
                       extractSurface(c.geometry, maskToField(c.geometry, c.masks.spleen)),
                       exports::MeshFormat::Stl);
    EXPECT_EQ(fileText(dir / "a.stl"), fileText(dir / "m.stl"));
    fs::remove_all(dir);
}

TEST(StructureExport, RefusesEachBadInputInOneLine) {
    const Case c(false);
    const fs::path dir = tempDir("structures-refuse");
    const std::vector<std::uint8_t> shortMask(5, 1);
    const std::vector<std::uint8_t> nothing(c.geometry.voxelCount(), 0);
    struct Bad {
        std::string what;
        std::function<void(exports::StructuresExport&)> change;
        model::ExportFormat format = model::ExportFormat::NiftiGz;
    };
    const std::vector<Bad> cases{
        {"no structure to export", [](auto& d) { d.structures.clear(); }},
        {"two structures are named 'Liver'",
         [](auto& d) { d.structures[2].segment.name = "Liver"; }},
        {"structure 2 has no name", [](auto& d) { d.structures[1].segment.name = ""; }},
        {"structure 'Spleen': the label value must be within 1..255 (got 256)",
         [](auto& d) { d.structures[1].segment.label = 256; }},
        {"structure 'Spleen': the label value must be within 1..255 (got 0)",
         [](auto& d) { d.structures[1].segment.label = 0; }},
        {"structure 'Liver' and structure 'Left kidney' have the same label value 1",
         [](auto& d) { d.structures[2].segment.label = 1; }},
        {"structure 'Spleen': the mask has 5 voxels but the grid 24x20x10 has 4800",
         [&](auto& d) { d.structures[1].mask = shortMask; }},
        {"structure 3: a name must not hold a line break or '|'",
         [](auto& d) { d.structures[2].segment.name = "Left\nkidney"; }},
        {"structure 3: a name must not hold a line break or '|'",
         [](auto& d) { d.structures[2].segment.name = "Left|kidney"; }},
        {"structure 'Liver': colour components must be within 0..1",
         [](auto& d) { d.structures[0].segment.color.b = 1.5; }},
        {"TIFF holds one structure", [](auto&) {}, model::ExportFormat::Tiff},
        {"structure 'Spleen' has no surface (nothing is inside it)",
         [&](auto& d) { d.structures[1].mask = nothing; }, model::ExportFormat::Ply},
        {"DICOM SEG needs a scan read from a DICOM series", [](auto&) {},
         model::ExportFormat::DicomSeg},
    };
    for (const Bad& bad : cases) {
        SCOPED_TRACE(bad.what);
        exports::StructuresExport data = c.data();
        bad.change(data);
        const fs::path out = dir / "out";
        try {
            exports::writeStructures(out, bad.format, data);
            ADD_FAILURE() << "no error";
        } catch (const files::WriteError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(bad.what), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
        EXPECT_TRUE(fs::is_empty(dir));
    }
    fs::remove_all(dir);
}

} // namespace steerseg::test
