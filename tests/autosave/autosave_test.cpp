#include "autosave/autosave_snapshot.hpp"
#include "autosave/autosave_store.hpp"
#include "autosave/autosave_writer.hpp"
#include "workflow/param_ranges.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <zlib.h>

namespace steerseg::test {
namespace {

using namespace autosave;
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / "autosave" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A ball in a 20 x 16 x 12 grid, and everything else set to something other than its default.
AutosaveSnapshot sampleSnapshot(std::int64_t savedAtMs = 1'700'000'000'123) {
    AutosaveSnapshot s;
    s.scan = {"/data/scan.nii.gz", 123456, 1'600'000'000'000'000'007};
    s.dims = {20, 16, 12};
    s.savedAtMs = savedAtMs;
    s.sequence = 9;
    s.state = model::State::Evolving;
    s.params.values[workflow::indexOf(model::Param::T)] = 812.25;
    s.params.values[workflow::indexOf(model::Param::Eps)] = 150.0;
    s.params.values[workflow::indexOf(model::Param::Alpha)] = 0.9;
    s.params.values[workflow::indexOf(model::Param::Radius)] = 4.5;
    s.params.preset = "CT soft tissue";
    s.params.speed = {model::SpeedKind::Classify,
                      {{{1.0F, 2.0F, 3.0F}, 1.5F}},
                      {{{4.0F, 5.0F, 6.0F}, 2.0F}, {{7.0F, 8.0F, 9.0F}, 0.5F}}};
    s.params.speed.box = model::Box{{2, 3, 1}, {17, 13, 10}};
    s.params.fallback = model::SpeedKind::Edge;
    s.seeds = 2;
    s.erasures = 1;
    s.iterations = 340;
    s.evolvedTime = 12.5;
    s.barriers = {{{{3.0F, 4.0F, 5.0F}, 2.0F}, false},
                  {{{12.5F, 8.0F, 6.0F}, 1.5F}, true},
                  {{{9.0F, 8.0F, 6.0F}, 2.0F}, true, model::TissueLevel{143.5F, 6.0F}}};
    std::vector<std::uint8_t> mask(20 * 16 * 12, 0);
    for (int k = 0; k < 12; ++k) {
        for (int j = 0; j < 16; ++j) {
            for (int i = 0; i < 20; ++i) {
                const int di = i - 10;
                const int dj = j - 8;
                const int dk = k - 6;
                if (di * di + dj * dj + dk * dk <= 25) {
                    mask[static_cast<std::size_t>((k * 16 + j) * 20 + i)] = 1;
                }
            }
        }
    }
    s.mask = encodeRuns(mask);
    return s;
}

void expectSame(const AutosaveSnapshot& a, const AutosaveSnapshot& b) {
    EXPECT_EQ(a.scan, b.scan);
    EXPECT_EQ(a.dims, b.dims);
    EXPECT_EQ(a.savedAtMs, b.savedAtMs);
    EXPECT_EQ(a.sequence, b.sequence);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(a.seeds, b.seeds);
    EXPECT_EQ(a.erasures, b.erasures);
    EXPECT_EQ(a.iterations, b.iterations);
    EXPECT_EQ(a.evolvedTime, b.evolvedTime);
    EXPECT_EQ(a.barriers, b.barriers);
    EXPECT_EQ(a.mask.voxels, b.mask.voxels);
    EXPECT_EQ(a.mask.runs, b.mask.runs);
}

std::string decodeError(const std::vector<std::byte>& bytes) {
    try {
        (void)decodeSnapshot(bytes);
    } catch (const AutosaveFormatError& e) {
        return e.what();
    }
    return "(decoded)";
}

// `bytes` with `from` in the metadata replaced by `to` and the header's length and CRC made
// whole again: a file that decodes as far as its JSON, as another writer could leave one.
std::vector<std::byte> withMetadata(std::vector<std::byte> bytes, const std::string& from,
                                    const std::string& to) {
    constexpr std::size_t kHeader = 36, kMetaLength = 12, kCrc = 32;
    std::string text(reinterpret_cast<const char*>(bytes.data()) + kHeader, bytes.size() - kHeader);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    const std::uint32_t metaBytes = std::to_integer<std::uint32_t>(bytes[kMetaLength]) |
                                    std::to_integer<std::uint32_t>(bytes[kMetaLength + 1]) << 8U |
                                    std::to_integer<std::uint32_t>(bytes[kMetaLength + 2]) << 16U |
                                    std::to_integer<std::uint32_t>(bytes[kMetaLength + 3]) << 24U;
    text.replace(at, from.size(), to);
    const auto put = [&](std::size_t offset, std::uint32_t v) {
        for (std::size_t b = 0; b < 4; ++b) {
            bytes[offset + b] = static_cast<std::byte>(v >> (8U * b));
        }
    };
    bytes.resize(kHeader);
    for (const char c : text) {
        bytes.push_back(static_cast<std::byte>(c));
    }
    put(kMetaLength, static_cast<std::uint32_t>(metaBytes + to.size() - from.size()));
    put(kCrc, static_cast<std::uint32_t>(crc32(0L, reinterpret_cast<const Bytef*>(text.data()),
                                               static_cast<uInt>(text.size()))));
    return bytes;
}

TEST(AutosaveFormat, NumbersNoFloatHoldsAreOneClearError) {
    const std::vector<std::byte> good = encodeSnapshot(sampleSnapshot());
    ASSERT_EQ(decodeError(withMetadata(good, "143.5", "143.25")), "(decoded)");
    // A barrier's tissue level, then a sphere's coordinate: 1e39 is a double but no float.
    for (const char* at : {"143.5", "12.5"}) {
        SCOPED_TRACE(at);
        EXPECT_NE(decodeError(withMetadata(good, at, "-1e39")).find("out of range"),
                  std::string::npos);
        EXPECT_NE(decodeError(withMetadata(good, at, "1e400")).find("bad metadata"),
                  std::string::npos)
            << "the JSON parser's own refusal";
    }
}

TEST(AutosaveFormat, RoundTripKeepsEverything) {
    const AutosaveSnapshot s = sampleSnapshot();
    expectSame(decodeSnapshot(encodeSnapshot(s)), s);
}

// A box that no longer fits the saved grid is the autosave's error, named, not the resumed
// session's; a snapshot from before the box has none.
TEST(AutosaveFormat, TheBoxComesBackOrIsOneClearError) {
    const std::vector<std::byte> good = encodeSnapshot(sampleSnapshot());
    EXPECT_NE(decodeError(withMetadata(good, "\"hi\":[17,13,10]", "\"hi\":[17,13,12]"))
                  .find("reaches outside the scan"),
              std::string::npos);
    EXPECT_NE(decodeError(withMetadata(good, "\"hi\":[17,13,10]", "\"hi\":[1,13,10]"))
                  .find("inverted on i"),
              std::string::npos);
    AutosaveSnapshot none = sampleSnapshot();
    none.params.speed.box.reset();
    expectSame(decodeSnapshot(encodeSnapshot(none)), none);
}

TEST(AutosaveFormat, RoundTripWithoutALevelSet) {
    AutosaveSnapshot s = sampleSnapshot();
    s.mask = {};
    s.state = model::State::Inspect;
    expectSame(decodeSnapshot(encodeSnapshot(s)), s);
}

// Several structures: the active one's surface is the snapshot's mask, every other one's runs
// follow it in the file, with its description, parameters and counts in the metadata.
AutosaveSnapshot withStructures() {
    AutosaveSnapshot s = sampleSnapshot();
    workflow::StructureList list;
    workflow::Structure liver;
    liver.info = {"Liver",
                  {"123037004", "SCT", "Anatomical Structure"},
                  {"10200004", "SCT", "Liver"},
                  {0.8, 0.5, 0.4},
                  false};
    std::vector<std::uint8_t> slab(20 * 16 * 12, 0);
    std::fill(slab.begin(), slab.begin() + 20 * 16 * 2, std::uint8_t{1});
    liver.mask = encodeRuns(slab);
    liver.params = s.params;
    liver.params.values[workflow::indexOf(model::Param::T)] = 60.0;
    liver.params.speed.box.reset();
    liver.seeds = 3;
    liver.volumeMl = 1.25;
    workflow::Structure active;
    active.info.name = "Spleen";
    workflow::Structure empty;
    empty.info.name = "Left kidney";
    list.items = {liver, active, empty};
    list.active = 1;
    s.structures = list;
    return s;
}

TEST(AutosaveFormat, EveryStructureComesBack) {
    const AutosaveSnapshot s = withStructures();
    const AutosaveSnapshot back = decodeSnapshot(encodeSnapshot(s));
    expectSame(back, s);
    ASSERT_TRUE(back.structures.has_value());
    ASSERT_EQ(back.structures->items.size(), 3U);
    EXPECT_EQ(back.structures->active, 1U);
    for (std::size_t i = 0; i < 3; ++i) {
        const workflow::Structure& a = s.structures->items[i];
        const workflow::Structure& b = back.structures->items[i];
        EXPECT_EQ(a.info, b.info) << i;
        EXPECT_EQ(a.mask.runs, b.mask.runs) << i;
        EXPECT_EQ(a.seeds, b.seeds) << i;
        EXPECT_EQ(a.volumeMl, b.volumeMl) << i;
        if (i != 1) {
            EXPECT_EQ(a.params, b.params) << i;
        }
    }
    // The active one without a surface: the others still come back.
    AutosaveSnapshot bare = withStructures();
    bare.mask = {};
    const AutosaveSnapshot bareBack = decodeSnapshot(encodeSnapshot(bare));
    EXPECT_TRUE(bareBack.mask.runs.empty());
    EXPECT_EQ(bareBack.structures->items[0].mask.runs, bare.structures->items[0].mask.runs);
    // Garbled: a run count that does not fit, a name no session allows, a code left empty.
    const std::vector<std::byte> good = encodeSnapshot(s);
    EXPECT_NE(decodeError(withMetadata(good, "\"name\":\"Liver\"", "\"name\":\"a|b\"")).find("'|'"),
              std::string::npos);
    EXPECT_NE(decodeError(withMetadata(good, "\"10200004\"", "\"\"")).find("code"),
              std::string::npos);
    EXPECT_NE(decodeError(withMetadata(good, "\"active\":1", "\"active\":5")).find("active"),
              std::string::npos);
}

TEST(AutosaveFormat, EveryCorruptionIsOneClearError) {
    const std::vector<std::byte> good = encodeSnapshot(sampleSnapshot());
    auto badMagic = good;
    badMagic[0] = std::byte{'X'};
    EXPECT_NE(decodeError(badMagic).find("magic"), std::string::npos);

    auto badVersion = good;
    badVersion[8] = std::byte{7};
    EXPECT_NE(decodeError(badVersion).find("version 7"), std::string::npos);

    const std::vector<std::byte> shortHeader(good.begin(), good.begin() + 20);
    EXPECT_NE(decodeError(shortHeader).find("truncated"), std::string::npos);

    // A write cut off anywhere inside the payload.
    for (const std::size_t keep :
         {good.size() - 1, good.size() - 4, good.size() / 2, std::size_t{40}}) {
        const std::vector<std::byte> cut(good.begin(), good.begin() + static_cast<long>(keep));
        EXPECT_NE(decodeError(cut).find("truncated"), std::string::npos) << keep;
    }

    auto longer = good;
    longer.push_back(std::byte{0});
    EXPECT_NE(decodeError(longer).find("past the end"), std::string::npos);

    // One flipped bit in the metadata, and one in the runs.
    for (const std::size_t at : {std::size_t{50}, good.size() - 2}) {
        auto flipped = good;
        flipped[at] ^= std::byte{0x10};
        EXPECT_NE(decodeError(flipped).find("CRC"), std::string::npos) << at;
    }

    auto hugeSizes = good;
    hugeSizes[31] = std::byte{0x7f}; // voxels' top byte
    EXPECT_NE(decodeError(hugeSizes).find("implausible"), std::string::npos);
}

TEST(AutosaveFormat, ScanReferenceTellsAChangedFile) {
    const fs::path dir = freshDir("reference");
    const fs::path scan = dir / "scan.nrrd";
    std::ofstream(scan) << "twelve bytes";
    const ScanReference before = referenceOf(scan.string());
    EXPECT_EQ(before.bytes, 12U);
    EXPECT_NE(before.mtimeNs, 0);
    EXPECT_EQ(differenceBetween(before, referenceOf(scan.string())), "");
    std::ofstream(scan) << "thirteen byte";
    EXPECT_NE(differenceBetween(before, referenceOf(scan.string())).find("changed"),
              std::string::npos);
    ScanReference other = before;
    other.path = "/elsewhere.nrrd";
    EXPECT_NE(differenceBetween(other, before).find("not"), std::string::npos);
}

TEST(AutosaveStore, RotationKeepsTheNewestAndTheManifestListsThem) {
    const fs::path dir = freshDir("rotation");
    AutosaveStore store(dir, 3);
    std::vector<fs::path> written;
    for (int n = 0; n < 5; ++n) {
        written.push_back(store.save(sampleSnapshot(1000 + n)));
    }
    EXPECT_FALSE(fs::exists(written[0]));
    EXPECT_FALSE(fs::exists(written[1]));
    for (int n = 2; n < 5; ++n) {
        EXPECT_TRUE(fs::exists(written[static_cast<std::size_t>(n)])) << n;
    }
    const Manifest m = readManifest(dir);
    ASSERT_EQ(m.files.size(), 3U);
    EXPECT_FALSE(m.clean);
    for (std::size_t i = 0; i < 3; ++i) {
        const ManifestEntry& e = m.files[i];
        EXPECT_EQ(e.file, written[i + 2].filename().string());
        EXPECT_EQ(e.savedAtMs, 1002 + static_cast<std::int64_t>(i));
        EXPECT_EQ(e.bytes, fs::file_size(written[i + 2]));
        std::ifstream in(written[i + 2], std::ios::binary);
        std::vector<char> raw(static_cast<std::size_t>(fs::file_size(written[i + 2])));
        in.read(raw.data(), static_cast<std::streamsize>(raw.size()));
        EXPECT_EQ(e.crc, snapshotCrc(std::as_bytes(std::span<const char>(raw))));
        EXPECT_EQ(e.state, "evolving");
    }
    std::vector<std::string> problems;
    const auto found = AutosaveStore(dir, 3).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(found->file, written[4]);
    EXPECT_EQ(found->snapshot.savedAtMs, 1004);
    EXPECT_FALSE(found->clean);
}

TEST(AutosaveStore, ANewSessionNumbersOnWithoutOverwriting) {
    const fs::path dir = freshDir("numbering");
    const fs::path first = AutosaveStore(dir, 5).save(sampleSnapshot(1));
    const fs::path second = AutosaveStore(dir, 5).save(sampleSnapshot(2));
    EXPECT_NE(first, second);
    EXPECT_EQ(readSnapshotFile(first).savedAtMs, 1);
    EXPECT_EQ(readSnapshotFile(second).savedAtMs, 2);
}

// Each way the newest can be bad: the one before it is used, with a line saying why.
TEST(AutosaveStore, DamagedNewestFallsBackToThePreviousOne) {
    struct Damage {
        const char* name;
        void (*apply)(const fs::path&);
        const char* says;
    };
    const Damage damages[] = {
        {"flipped",
         [](const fs::path& p) {
             std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
             f.seekp(60);
             f.put('#');
         },
         "CRC"},
        {"truncated", [](const fs::path& p) { fs::resize_file(p, fs::file_size(p) / 2); },
         "truncated"},
        {"missing", [](const fs::path& p) { fs::remove(p); }, "missing"},
        {"version",
         [](const fs::path& p) {
             std::fstream f(p, std::ios::in | std::ios::out | std::ios::binary);
             f.seekp(8);
             f.put('\x02');
         },
         "version 2"},
        {"empty", [](const fs::path& p) { std::ofstream(p, std::ios::trunc); }, "magic"},
    };
    for (const Damage& d : damages) {
        const fs::path dir = freshDir(std::string("damaged-") + d.name);
        fs::path newest;
        {
            AutosaveStore store(dir, 4);
            store.save(sampleSnapshot(100));
            store.save(sampleSnapshot(200));
            newest = store.save(sampleSnapshot(300));
        }
        d.apply(newest);
        std::vector<std::string> problems;
        const auto found = AutosaveStore(dir, 4).newest(problems);
        ASSERT_TRUE(found) << d.name;
        EXPECT_EQ(found->snapshot.savedAtMs, 200) << d.name;
        ASSERT_EQ(problems.size(), 1U) << d.name;
        EXPECT_NE(problems[0].find(d.says), std::string::npos) << d.name << ": " << problems[0];
        EXPECT_NE(problems[0].find(newest.filename().string()), std::string::npos) << problems[0];
    }
}

// A whole autosave that is not the one the manifest lists (a rename, a copy from elsewhere).
TEST(AutosaveStore, AFileOtherThanTheManifestSaysIsPassedOver) {
    const fs::path dir = freshDir("manifest-mismatch");
    fs::path newest;
    {
        AutosaveStore store(dir, 4);
        store.save(sampleSnapshot(100));
        newest = store.save(sampleSnapshot(200));
    }
    AutosaveSnapshot other = sampleSnapshot(200);
    other.sequence = 2;
    other.seeds = 7; // same size, different content
    const std::vector<std::byte> bytes = encodeSnapshot(other);
    std::ofstream(newest, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    std::vector<std::string> problems;
    const auto found = AutosaveStore(dir, 4).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->snapshot.savedAtMs, 100);
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_NE(problems[0].find("the manifest says"), std::string::npos) << problems[0];
}

TEST(AutosaveStore, DamagedManifestFallsBackToTheFolder) {
    const fs::path dir = freshDir("manifest-damaged");
    {
        AutosaveStore store(dir, 4);
        store.save(sampleSnapshot(100));
        store.save(sampleSnapshot(200));
    }
    std::ofstream(dir / "manifest.json", std::ios::trunc) << "{\"format\": \"steerseg-aut";
    std::vector<std::string> problems;
    const auto found = AutosaveStore(dir, 4).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->snapshot.savedAtMs, 200);
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_NE(problems[0].find("manifest.json: damaged"), std::string::npos) << problems[0];
    EXPECT_FALSE(found->clean); // without a manifest nobody said the session ended
}

TEST(AutosaveStore, NothingUsableIsNoResumeWithEveryReason) {
    const fs::path dir = freshDir("nothing");
    std::vector<std::string> problems;
    EXPECT_FALSE(AutosaveStore(dir, 2).newest(problems));
    EXPECT_TRUE(problems.empty()); // a first start: no manifest, no autosaves
    {
        AutosaveStore store(dir, 2);
        fs::resize_file(store.save(sampleSnapshot(1)), 30);
    }
    problems.clear();
    EXPECT_FALSE(AutosaveStore(dir, 2).newest(problems));
    EXPECT_EQ(problems.size(), 1U);
    fs::remove(dir / "manifest.json"); // a manifest lost with autosaves left: said
    problems.clear();
    EXPECT_FALSE(AutosaveStore(dir, 2).newest(problems));
    EXPECT_EQ(problems.size(), 2U);
}

TEST(AutosaveStore, CleanEndIsRecordedAndNewWorkReopens) {
    const fs::path dir = freshDir("clean");
    AutosaveStore store(dir, 2);
    store.save(sampleSnapshot(1));
    store.markClean();
    std::vector<std::string> problems;
    auto found = AutosaveStore(dir, 2).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_TRUE(found->clean);
    store.save(sampleSnapshot(2));
    found = AutosaveStore(dir, 2).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_FALSE(found->clean);
}

TEST(AutosaveWriter, WritesOffTheCallersThreadAndReportsFailures) {
    const fs::path dir = freshDir("writer");
    AutosaveStore store(dir, 3);
    {
        AutosaveWriter writer(store);
        for (int n = 0; n < 10; ++n) {
            writer.submit(sampleSnapshot(n));
        }
        writer.flush();
        EXPECT_GE(writer.written(), 1U);
        EXPECT_LE(writer.written(), 10U); // queued ones are replaced by newer ones
        EXPECT_FALSE(writer.takeError());
        writer.markClean();
    } // the destructor writes what is queued
    std::vector<std::string> problems;
    const auto found = AutosaveStore(dir, 3).newest(problems);
    ASSERT_TRUE(found);
    EXPECT_EQ(found->snapshot.savedAtMs, 9); // the last one handed over is never dropped
    EXPECT_TRUE(found->clean);

    // A folder that cannot be created: a file stands where it should be.
    const fs::path blocked = freshDir("writer-blocked") / "file";
    std::ofstream(blocked) << "x";
    AutosaveStore bad(blocked / "autosave", 3);
    AutosaveWriter failing(bad);
    failing.submit(sampleSnapshot());
    failing.flush();
    const auto error = failing.takeError();
    ASSERT_TRUE(error);
    EXPECT_NE(error->find("autosave"), std::string::npos) << *error;
    EXPECT_FALSE(failing.takeError()); // reported once
    EXPECT_EQ(failing.written(), 0U);
}

} // namespace
} // namespace steerseg::test
