// Issue 25's fault-injection suite: every file the product writes, driven through each fault a
// failing disk or a wrong set-up gives, at every system call of that kind the write makes in
// turn (files::IoFault, the seam in the durable write path), plus a missing folder and a folder
// in the way for real. For each: files::WriteError in one line naming the file and the cause,
// the previous file as it was, no temporary left behind, and a retry once the fault is gone
// that succeeds. docs/reliability.md has the table of writers and what the operator sees.
#include "autosave/autosave_store.hpp"
#include "exports/export_writer.hpp"
#include "exports/image_file.hpp"
#include "files/file_append.hpp"
#include "files/file_error.hpp"
#include "files/io_faults.hpp"
#include "kiosk/frame_stats.hpp"
#include "model/export_format.hpp"
#include "platform/input/recording.hpp"
#include "scan/dicom_source.hpp"
#include "support/write_faults.hpp"
#include "workflow/audit_log.hpp"

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::test {
namespace {

namespace fs = std::filesystem;
using files::IoCall;

constexpr std::string_view kPrevious = "the previous version\n";

// A ball in a small oblique-free grid: every format has something to write.
struct Segmentation {
    Geometry geometry;
    std::vector<std::uint8_t> mask;
    scan::DicomSource dicom;
    Segmentation() {
        geometry.dims = {12, 10, 8};
        geometry.spacing = {0.8, 0.8, 1.5};
        mask.resize(geometry.voxelCount());
        for (int k = 0; k < 8; ++k) {
            for (int j = 0; j < 10; ++j) {
                for (int i = 0; i < 12; ++i) {
                    const double r2 = (i - 6) * (i - 6) + (j - 5) * (j - 5) + (k - 4) * (k - 4);
                    mask[static_cast<std::size_t>(i + 12 * (j + 10 * k))] = r2 < 9.0 ? 1 : 0;
                }
            }
        }
        dicom.studyInstanceUid = "1.2.826.0.1.3680043.8.498.1";
        dicom.seriesInstanceUid = "1.2.826.0.1.3680043.8.498.2";
        dicom.frameOfReferenceUid = "1.2.826.0.1.3680043.8.498.3";
        dicom.patientId = "FAULTS";
        dicom.inherited = {{0x0010, 0x0020, dicom.patientId},
                           {0x0020, 0x000D, dicom.studyInstanceUid},
                           {0x0020, 0x0052, dicom.frameOfReferenceUid}};
        for (int k = 0; k < 8; ++k) {
            dicom.slices.push_back({"1.2.840.10008.5.1.4.1.1.2",
                                    "1.2.826.0.1.3680043.8.498.10." + std::to_string(k), 0,
                                    glm::dvec3(0.0, 0.0, 1.5 * k)});
        }
    }
    [[nodiscard]] exports::ExportData data() const { return {geometry, mask, {}, {}, &dicom}; }
};

const Segmentation& segmentation() {
    static const Segmentation s;
    return s;
}

RgbaImage picture() {
    RgbaImage image{32, 24, {}};
    image.pixels.assign(32u * 24u * 4u, 200);
    return image;
}

// A writer that replaces one file (the durable write: temporary, fsync, rename).
struct FileWriter {
    std::string name;
    std::string file; // the name it writes in the test's folder
    std::function<void(const fs::path&)> write;
};

std::vector<FileWriter> fileWriters() {
    std::vector<FileWriter> out;
    for (const model::ExportFormat format : model::exportFormats()) {
        const std::string ext(model::exportFormatName(format));
        out.push_back({"export ." + ext, "mask." + ext, [format](const fs::path& p) {
                           exports::writeExport(p, format, segmentation().data());
                       }});
    }
    out.push_back({"frame picture .png", "frame.png",
                   [](const fs::path& p) { exports::writeImage(p, picture()); }});
    out.push_back({"frame statistics .json", "stats.json", [](const fs::path& p) {
                       kiosk::FrameStats stats;
                       stats.frame(0.016, true);
                       stats.write(p, "faults");
                   }});
    return out;
}

struct Fault {
    std::string name;
    IoCall call;
    int error;
    std::string words; // in the message
};

const std::vector<Fault>& injectedFaults() {
    static const std::vector<Fault> faults{
        {"ENOSPC on write", IoCall::Write, ENOSPC, "the disk is full"},
        {"EIO on write", IoCall::Write, EIO, "Input/output error"},
        {"EIO on fsync", IoCall::Sync, EIO, "Input/output error"},
        {"ENOSPC on fsync", IoCall::Sync, ENOSPC, "the disk is full"},
        {"EACCES on open", IoCall::Open, EACCES, "not writable (permission denied)"},
        {"EROFS on open", IoCall::Open, EROFS, "read-only file system"},
        {"EIO on rename", IoCall::Rename, EIO, "Input/output error"},
    };
    return faults;
}

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(testing::TempDir()) / "faults-every-writer" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writePrevious(const fs::path& path) {
    std::ofstream(path, std::ios::binary) << kPrevious;
}

// How many calls of each kind one clean write makes.
std::array<std::size_t, files::kIoCallCount> callsOf(const std::function<void()>& write) {
    const files::IoFault counting(IoCall::Open, -1, 0);
    write();
    std::array<std::size_t, files::kIoCallCount> n{};
    for (std::size_t c = 0; c < n.size(); ++c) {
        n[c] = counting.calls(static_cast<IoCall>(c));
    }
    return n;
}

std::size_t at(const std::array<std::size_t, files::kIoCallCount>& n, IoCall call) {
    return n[static_cast<std::size_t>(call)];
}

// A folder made afresh holding the previous version of `previous`.
void freshWithPrevious(const fs::path& dir, const fs::path& previous) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    writePrevious(previous);
}

// Each injected fault at each call of its kind in turn: `prepare` sets the scene unarmed, then
// `attempt` runs with the fault armed (the calls after the failing one go through: a retry in
// it finds the fault gone). Returns the number of cases.
std::size_t atEveryCall(const std::array<std::size_t, files::kIoCallCount>& calls,
                        const std::function<void()>& prepare,
                        const std::function<void(const Fault&, const files::IoFault&)>& attempt) {
    std::size_t cases = 0;
    for (const Fault& f : injectedFaults()) {
        for (std::size_t nth = 0; nth < at(calls, f.call); ++nth) {
            SCOPED_TRACE(f.name + ", call " + std::to_string(nth));
            prepare();
            const files::IoFault fault(f.call, static_cast<int>(nth), f.error);
            attempt(f, fault);
            EXPECT_TRUE(fault.fired());
            ++cases;
        }
    }
    return cases;
}

void expectOneLine(const std::string& m, const fs::path& path, const std::string& words) {
    EXPECT_NE(m.find(path.string() + ": "), std::string::npos) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(FaultsEveryWriter, EveryFileWriterAtEveryCallOfEveryFault) {
    std::size_t cases = 0;
    for (const FileWriter& w : fileWriters()) {
        SCOPED_TRACE(w.name);
        const fs::path dir = freshDir("file");
        const fs::path target = dir / w.file;
        const auto calls = callsOf([&] { w.write(target); });
        ASSERT_GE(at(calls, IoCall::Write), 1u);
        const auto prepare = [&] { freshWithPrevious(dir, target); };
        cases += atEveryCall(calls, prepare, [&](const Fault& f, const files::IoFault&) {
            expectOneLine(writeErrorOf([&] { w.write(target); }), target, f.words);
            EXPECT_EQ(readText(target), kPrevious);
            EXPECT_EQ(entryCount(dir), 1u) << "a temporary was left behind";
            ASSERT_EQ(writeErrorOf([&] { w.write(target); }), "") << "the retry";
            EXPECT_NE(readText(target), kPrevious);
            EXPECT_EQ(entryCount(dir), 1u);
        });
        // After the rename only the folder's sync can fail: the new file is whole and in place,
        // and the write still says that it may not survive a power cut.
        {
            prepare();
            const files::IoFault fault(IoCall::SyncFolder, 0, EIO);
            expectOneLine(writeErrorOf([&] { w.write(target); }), target, "Input/output error");
            EXPECT_NE(readText(target), kPrevious);
            EXPECT_EQ(entryCount(dir), 1u);
        }
        // A missing folder and a folder in the way, for real.
        const std::string missing =
            writeErrorOf([&] { w.write(dir / "gone" / "deeper" / w.file); });
        expectOneLine(missing, dir / "gone" / "deeper" / w.file, "does not exist");
        fs::remove_all(dir);
        fs::create_directories(target);
        expectOneLine(writeErrorOf([&] { w.write(target); }), target,
                      "a folder of that name is in the way");
        EXPECT_TRUE(fs::is_directory(target));
        EXPECT_EQ(entryCount(dir), 1u);
        fs::remove(target);
        ASSERT_EQ(writeErrorOf([&] { w.write(target); }), "");
        cases += 3;
    }
    EXPECT_GE(cases, 100u);
}

autosave::AutosaveSnapshot snapshot(std::uint64_t seeds) {
    autosave::AutosaveSnapshot s;
    s.scan = {"builtin:sample", 0, 0};
    s.dims = segmentation().geometry.dims;
    s.savedAtMs = 1'700'000'000'000;
    s.state = model::State::Paused;
    s.seeds = static_cast<int>(seeds);
    s.mask = encodeRuns(segmentation().mask);
    return s;
}

// No hidden temporary files in the autosave folder.
std::size_t temporaries(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
        n += e.path().filename().string().starts_with(".") ? 1 : 0;
    }
    return n;
}

// The autosave writes a snapshot and then its manifest: whichever call fails, the folder's
// newest readable autosave is the previous one or the new one, whole, and the next save works.
TEST(FaultsEveryWriter, AutosaveAndItsManifestAtEveryCall) {
    const fs::path dir = freshDir("autosave");
    autosave::AutosaveStore first(dir, 3);
    first.save(snapshot(1));
    const auto calls = callsOf([&] { first.save(snapshot(2)); });
    std::optional<autosave::AutosaveStore> store;
    const auto prepare = [&] {
        fs::remove_all(dir);
        store.emplace(dir, 3);
        store->save(snapshot(1));
    };
    const std::size_t cases =
        atEveryCall(calls, prepare, [&](const Fault& f, const files::IoFault&) {
            const std::string m = writeErrorOf([&] { store->save(snapshot(2)); });
            EXPECT_NE(m.find(dir.string()), std::string::npos) << m;
            EXPECT_NE(m.find(f.words), std::string::npos) << m;
            EXPECT_EQ(temporaries(dir), 0u);
            std::vector<std::string> problems;
            const auto found = autosave::AutosaveStore(dir, 3).newest(problems);
            ASSERT_TRUE(found.has_value());
            EXPECT_TRUE(found->snapshot.seeds == 1 || found->snapshot.seeds == 2);
            ASSERT_EQ(writeErrorOf([&] { store->save(snapshot(3)); }), "") << "the retry";
            const auto after = autosave::AutosaveStore(dir, 3).newest(problems);
            ASSERT_TRUE(after.has_value());
            EXPECT_EQ(after->snapshot.seeds, 3);
        });
    EXPECT_GE(cases, 8u);
    // A file where the folder should be.
    fs::remove_all(dir);
    writePrevious(dir);
    EXPECT_NE(writeErrorOf([&] {
                  autosave::AutosaveStore blocked(dir, 3);
                  blocked.save(snapshot(1));
              }),
              "");
    EXPECT_EQ(readText(dir), kPrevious);
    fs::remove(dir);
}

std::chrono::steady_clock::time_point secondsIn(double s) {
    return std::chrono::steady_clock::time_point(
        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
            std::chrono::duration<double>(s)));
}

// The audit log appends: a failed record leaves the file as it was (no partial line), the log
// says why in problem() for the screen, and the next try writes what was held, in order.
TEST(FaultsEveryWriter, AuditLogAtEveryCall) {
    const fs::path dir = freshDir("audit");
    const fs::path path = dir / "audit.jsonl";
    const auto record = [](workflow::AuditLog& log) {
        log.transition(model::State::NoScan, model::State::Loading, "load_scan", "s", "");
    };
    const auto calls = callsOf([&] {
        workflow::AuditLog log(path);
        record(log);
    });
    const auto prepare = [&] { freshWithPrevious(dir, path); };
    const std::size_t cases =
        atEveryCall(calls, prepare, [&](const Fault& f, const files::IoFault& fault) {
            double now = 0.0;
            workflow::AuditLog log(path, {}, [&] { return secondsIn(now); });
            std::size_t made = 0;
            if (!fault.fired()) { // the opening failed already
                record(log);
                ++made;
            }
            ASSERT_FALSE(log.ok());
            EXPECT_NE(log.problem().find(path.string()), std::string::npos) << log.problem();
            EXPECT_NE(log.problem().find(f.words), std::string::npos) << log.problem();
            EXPECT_EQ(readText(path), kPrevious);
            EXPECT_EQ(entryCount(dir), 1u);
            log.retry();
            EXPECT_FALSE(log.ok()) << "retried within the second";
            now = 5.0;
            log.retry();
            ASSERT_TRUE(log.ok()) << log.problem();
            record(log);
            ++made;
            const workflow::AuditLogContents read = workflow::readAuditLog(path);
            EXPECT_EQ(read.records.size(), made);
            EXPECT_FALSE(read.torn);
            EXPECT_EQ(read.problems.size(), 1u) << "the previous text alone is no record";
        });
    EXPECT_GE(cases, 3u);
    fs::remove_all(dir);
    fs::create_directories(path);
    workflow::AuditLog blocked(path);
    EXPECT_NE(blocked.problem().find("a folder of that name is in the way"), std::string::npos)
        << blocked.problem();
}

// An input recording (input-monitor --record) grows record by record through files::AppendFile:
// a failed record is cut back, the ones before it stay, and the next one goes on.
TEST(FaultsEveryWriter, InputRecordingAtEveryCall) {
    const fs::path dir = freshDir("recording");
    const fs::path path = dir / "input.rec";
    const std::string line = platform::input::formatRecordLine(platform::input::RawRecord{}) + "\n";
    const auto calls = callsOf([&] { files::AppendFile(path).append(line); });
    const auto prepare = [&] { freshWithPrevious(dir, path); };
    const std::size_t cases =
        atEveryCall(calls, prepare, [&](const Fault& f, const files::IoFault&) {
            expectOneLine(writeErrorOf([&] { files::AppendFile(path).append(line); }), path,
                          f.words);
            EXPECT_EQ(readText(path), kPrevious);
            EXPECT_EQ(entryCount(dir), 1u);
            ASSERT_EQ(writeErrorOf([&] { files::AppendFile(path).append(line); }), "");
            EXPECT_EQ(readText(path), std::string(kPrevious) + line);
        });
    EXPECT_GE(cases, 3u);
    // A missing folder is made; one that cannot be (a file on the way) is named.
    EXPECT_EQ(writeErrorOf([&] { files::AppendFile(dir / "gone" / "x" / "in.rec"); }), "");
    expectOneLine(writeErrorOf([&] { files::AppendFile(path / "x" / "in.rec"); }),
                  path / "x" / "in.rec", "is not a folder");
    fs::remove_all(dir);
    fs::create_directories(path);
    expectOneLine(writeErrorOf([&] { files::AppendFile{path}; }), path,
                  "a folder of that name is in the way");
}

} // namespace
} // namespace steerseg::test
