// The autosave on disk: the header (magic, version, sizes, CRC32), the JSON metadata
// (autosave_metadata.cpp) and the mask's runs, and the scan reference a resume checks.
#include "autosave/autosave_snapshot.hpp"

#include "autosave/autosave_metadata.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <system_error>
#include <zlib.h>

namespace steerseg::autosave {

namespace {

constexpr std::array<char, 8> kMagic{'S', 'T', 'E', 'E', 'R', 'S', 'A', 'V'};
// magic, version, metadata bytes, run count, voxels, CRC32 of everything after the header.
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 8 + 8 + 4;
// The metadata is a few hundred bytes; more is not one of ours.
constexpr std::uint32_t kMaxMetaBytes = 1U << 20U;
// 2048^3: more voxels than any scan the loader accepts.
constexpr std::uint64_t kMaxVoxels = 1ULL << 33U;

void putLe(std::vector<std::byte>& out, std::uint64_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) {
        out.push_back(static_cast<std::byte>((value >> (8 * i)) & 0xFFU));
    }
}

std::uint64_t getLe(std::span<const std::byte> in, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) {
        v |= static_cast<std::uint64_t>(in[at + static_cast<std::size_t>(i)]) << (8 * i);
    }
    return v;
}

std::uint32_t crcOf(std::span<const std::byte> bytes) {
    uLong crc = crc32(0L, Z_NULL, 0);
    std::size_t at = 0;
    while (at < bytes.size()) { // zlib takes 32-bit lengths
        const std::size_t n = std::min<std::size_t>(bytes.size() - at, 1U << 30U);
        crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
        at += n;
    }
    return static_cast<std::uint32_t>(crc);
}

struct FileStamp {
    std::uint64_t bytes = 0;
    std::int64_t mtimeNs = 0;
};

std::int64_t mtimeNsOf(const std::filesystem::path& p, std::error_code& ec) {
    const auto t = std::filesystem::last_write_time(p, ec);
    return ec ? 0
              : std::chrono::duration_cast<std::chrono::nanoseconds>(t.time_since_epoch()).count();
}

} // namespace

ScanReference referenceOf(const std::string& path) {
    ScanReference ref;
    ref.path = path;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
        ref.bytes = std::filesystem::file_size(path, ec);
        ref.mtimeNs = mtimeNsOf(path, ec);
    } else if (std::filesystem::is_directory(path, ec)) {
        // A DICOM series: its files' total size and the newest of their times.
        for (const auto& entry : std::filesystem::directory_iterator(path, ec)) {
            std::error_code fileEc;
            if (entry.is_regular_file(fileEc)) {
                ref.bytes += entry.file_size(fileEc);
                ref.mtimeNs = std::max(ref.mtimeNs, mtimeNsOf(entry.path(), fileEc));
            }
        }
    }
    return ref;
}

std::string differenceBetween(const ScanReference& saved, const ScanReference& now) {
    if (saved.path != now.path) {
        return "the autosave is of " + saved.path + ", not " + now.path;
    }
    if (saved.bytes != now.bytes) {
        return saved.path + " changed since the autosave: " + std::to_string(now.bytes) +
               " bytes, was " + std::to_string(saved.bytes);
    }
    if (saved.mtimeNs != now.mtimeNs) {
        return saved.path + " changed since the autosave: its modification time differs";
    }
    return {};
}

std::vector<std::byte> encodeSnapshot(const AutosaveSnapshot& snapshot) {
    const std::string meta = metadata(snapshot).dump();
    // The active structure's runs, then each other structure's in the list's order.
    std::vector<const MaskRuns*> masks{&snapshot.mask};
    std::uint64_t voxels = snapshot.mask.voxels;
    if (snapshot.structures) {
        for (std::size_t i = 0; i < snapshot.structures->items.size(); ++i) {
            const MaskRuns& m = snapshot.structures->items[i].mask;
            if (i != snapshot.structures->active && !m.runs.empty()) {
                masks.push_back(&m);
                voxels = std::max<std::uint64_t>(voxels, m.voxels);
            }
        }
    }
    std::uint64_t runCount = 0;
    for (const MaskRuns* m : masks) {
        runCount += m->runs.size();
    }
    std::vector<std::byte> payload;
    payload.reserve(meta.size() + runCount * 4);
    for (const char c : meta) {
        payload.push_back(static_cast<std::byte>(c));
    }
    for (const MaskRuns* m : masks) {
        for (const std::uint32_t run : m->runs) {
            putLe(payload, run, 4);
        }
    }
    std::vector<std::byte> out;
    out.reserve(kHeaderBytes + payload.size());
    for (const char c : kMagic) {
        out.push_back(static_cast<std::byte>(c));
    }
    putLe(out, kAutosaveVersion, 4);
    putLe(out, meta.size(), 4);
    putLe(out, runCount, 8);
    putLe(out, voxels, 8);
    putLe(out, crcOf(payload), 4);
    out.insert(out.end(), payload.begin(), payload.end());
    return out;
}

std::uint32_t snapshotCrc(std::span<const std::byte> encoded) {
    if (encoded.size() < kHeaderBytes) {
        throw AutosaveFormatError("truncated: " + std::to_string(encoded.size()) +
                                  " bytes, shorter than the header");
    }
    return static_cast<std::uint32_t>(getLe(encoded, kHeaderBytes - 4, 4));
}

AutosaveSnapshot decodeSnapshot(std::span<const std::byte> bytes) {
    if (bytes.size() < kMagic.size() ||
        std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0) {
        throw AutosaveFormatError("not a steerseg autosave (bad magic)");
    }
    if (bytes.size() < kHeaderBytes) {
        throw AutosaveFormatError("truncated: " + std::to_string(bytes.size()) +
                                  " bytes, shorter than the header");
    }
    const auto version = static_cast<std::uint32_t>(getLe(bytes, 8, 4));
    if (version != kAutosaveVersion) {
        throw AutosaveFormatError("version " + std::to_string(version) + ", this build reads " +
                                  std::to_string(kAutosaveVersion));
    }
    const auto metaBytes = static_cast<std::uint32_t>(getLe(bytes, 12, 4));
    const std::uint64_t runCount = getLe(bytes, 16, 8);
    const std::uint64_t voxels = getLe(bytes, 24, 8);
    const auto crc = static_cast<std::uint32_t>(getLe(bytes, 32, 4));
    if (metaBytes > kMaxMetaBytes || voxels > kMaxVoxels ||
        runCount > (voxels + 1) * model::kMaxStructures) {
        throw AutosaveFormatError("implausible sizes in the header");
    }
    const std::uint64_t expected = kHeaderBytes + metaBytes + runCount * 4;
    if (bytes.size() < expected) {
        throw AutosaveFormatError("truncated: " + std::to_string(bytes.size()) + " bytes of " +
                                  std::to_string(expected));
    }
    if (bytes.size() > expected) {
        throw AutosaveFormatError(std::to_string(bytes.size() - expected) +
                                  " bytes past the end of the data");
    }
    const std::span<const std::byte> payload = bytes.subspan(kHeaderBytes);
    if (crcOf(payload) != crc) {
        throw AutosaveFormatError("CRC mismatch: the file is damaged");
    }
    AutosaveSnapshot s;
    std::vector<std::uint64_t> structureRuns;
    try {
        const auto* text = reinterpret_cast<const char*>(payload.data());
        const nlohmann::json meta = nlohmann::json::parse(text, text + metaBytes);
        readMetadata(meta, s);
        structureRuns = structureRunCounts(meta);
    } catch (const AutosaveFormatError&) {
        throw;
    } catch (const std::exception& e) {
        throw AutosaveFormatError(std::string("bad metadata: ") + e.what());
    }
    std::uint64_t others = 0;
    for (const std::uint64_t n : structureRuns) {
        others += n;
    }
    if (others > runCount || (s.structures && structureRuns.size() != s.structures->items.size())) {
        throw AutosaveFormatError("the structures' runs do not fit the file's");
    }
    std::uint64_t at = metaBytes;
    // Reads `count` runs into `mask`, which must cover the grid's voxels.
    const auto readRuns = [&](MaskRuns& mask, std::uint64_t count, const std::string& what) {
        mask.voxels = voxels;
        mask.runs.resize(count);
        std::uint64_t sum = 0;
        for (std::uint64_t i = 0; i < count; ++i, at += 4) {
            mask.runs[i] = static_cast<std::uint32_t>(getLe(payload, at, 4));
            sum += mask.runs[i];
        }
        if (count > 0 && sum != voxels) {
            throw AutosaveFormatError(what + "'s runs add up to " + std::to_string(sum) +
                                      " voxels, not " + std::to_string(voxels));
        }
    };
    readRuns(s.mask, runCount - others, "the mask");
    for (std::size_t i = 0; s.structures && i < s.structures->items.size(); ++i) {
        workflow::Structure& item = s.structures->items[i];
        if (i == s.structures->active && structureRuns[i] != 0) {
            throw AutosaveFormatError("the active structure's mask is the snapshot's own");
        }
        readRuns(item.mask, structureRuns[i], "structure '" + item.info.name + "'");
        if (item.mask.runs.empty()) {
            item.mask.voxels = 0;
        }
    }
    const std::uint64_t gridVoxels = static_cast<std::uint64_t>(std::max(s.dims.x, 0)) *
                                     static_cast<std::uint64_t>(std::max(s.dims.y, 0)) *
                                     static_cast<std::uint64_t>(std::max(s.dims.z, 0));
    if (runCount > 0 && gridVoxels != voxels) {
        throw AutosaveFormatError("the mask has " + std::to_string(voxels) +
                                  " voxels, the scan's grid " + std::to_string(gridVoxels));
    }
    return s;
}

AutosaveSnapshot readSnapshotFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!in || ec) {
        throw AutosaveFormatError(path.string() + ": cannot open it: " + std::strerror(errno));
    }
    std::vector<char> raw(static_cast<std::size_t>(size));
    in.read(raw.data(), static_cast<std::streamsize>(raw.size()));
    if (in.gcount() != static_cast<std::streamsize>(raw.size())) {
        throw AutosaveFormatError(path.string() + ": read failed");
    }
    try {
        return decodeSnapshot(std::as_bytes(std::span<const char>(raw)));
    } catch (const AutosaveFormatError& e) {
        throw AutosaveFormatError(path.string() + ": " + e.what());
    }
}

} // namespace steerseg::autosave
