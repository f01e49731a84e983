#include "autosave/autosave_store.hpp"

#include "files/file_write.hpp"
#include "workflow/utc_time.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <system_error>

namespace steerseg::autosave {

namespace {

constexpr const char* kManifestName = "manifest.json";
constexpr const char* kPrefix = "autosave-";
constexpr const char* kSuffix = ".ssav";

std::string fileNameFor(std::uint64_t sequence) {
    char name[64];
    std::snprintf(name, sizeof name, "%s%06llu%s", kPrefix,
                  static_cast<unsigned long long>(sequence), kSuffix);
    return name;
}

bool isAutosaveName(const std::string& name) {
    const std::string prefix = kPrefix;
    const std::string suffix = kSuffix;
    return name.size() > prefix.size() + suffix.size() && name.starts_with(prefix) &&
           name.ends_with(suffix);
}

nlohmann::json toJson(const Manifest& m) {
    nlohmann::json files = nlohmann::json::array();
    for (const ManifestEntry& e : m.files) {
        const auto saved =
            std::chrono::system_clock::time_point(std::chrono::milliseconds(e.savedAtMs));
        files.push_back({{"file", e.file},
                         {"sequence", e.sequence},
                         {"saved_at_ms", e.savedAtMs},
                         {"saved_at", workflow::isoUtc(saved)},
                         {"crc32", e.crc},
                         {"bytes", e.bytes},
                         {"state", e.state}});
    }
    return {{"format", "steerseg-autosave-manifest"},
            {"version", 1},
            {"clean", m.clean},
            {"files", files}};
}

// The CRC32 in a snapshot's header (the file has just been read whole and checked).
std::uint32_t headerCrc(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 64> head{};
    in.read(head.data(), head.size());
    return snapshotCrc(
        std::as_bytes(std::span<const char>(head.data(), static_cast<std::size_t>(in.gcount()))));
}

} // namespace

Manifest readManifest(const std::filesystem::path& folder) {
    const std::filesystem::path path = folder / kManifestName;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw std::runtime_error(path.string() + ": missing");
    }
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        if (j.at("format") != "steerseg-autosave-manifest" || j.at("version") != 1) {
            throw std::runtime_error("not a version 1 autosave manifest");
        }
        Manifest m;
        m.clean = j.at("clean").get<bool>();
        for (const nlohmann::json& f : j.at("files")) {
            ManifestEntry e;
            e.file = f.at("file").get<std::string>();
            if (!isAutosaveName(e.file) || e.file.find('/') != std::string::npos) {
                throw std::runtime_error("names a file that is not an autosave: " + e.file);
            }
            e.sequence = f.at("sequence").get<std::uint64_t>();
            e.savedAtMs = f.at("saved_at_ms").get<std::int64_t>();
            e.crc = f.at("crc32").get<std::uint32_t>();
            e.bytes = f.at("bytes").get<std::uint64_t>();
            e.state = f.at("state").get<std::string>();
            m.files.push_back(std::move(e));
        }
        return m;
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": damaged: " + e.what());
    }
}

AutosaveStore::AutosaveStore(std::filesystem::path folder, int keep)
    : folder_(std::move(folder)), keep_(static_cast<std::size_t>(std::max(keep, 1))) {
    std::string manifestProblem;
    try {
        manifest_ = readManifest(folder_);
    } catch (const std::exception& e) {
        manifestProblem = e.what();
    }
    // Numbers go on from the highest in the folder, listed or not, so no file is overwritten.
    std::error_code ec;
    bool anyFile = false;
    for (const auto& entry : std::filesystem::directory_iterator(folder_, ec)) {
        const std::string name = entry.path().filename().string();
        if (isAutosaveName(name)) {
            anyFile = true;
            const std::string digits =
                name.substr(std::string(kPrefix).size(), name.size() - std::string(kPrefix).size() -
                                                             std::string(kSuffix).size());
            try {
                nextSequence_ = std::max<std::uint64_t>(nextSequence_, std::stoull(digits) + 1);
            } catch (const std::exception&) {
                // Not one of ours after all.
            }
        }
    }
    for (const ManifestEntry& e : manifest_.files) {
        nextSequence_ = std::max(nextSequence_, e.sequence + 1);
    }
    // No manifest in a folder without autosaves is a first start, not a problem.
    if (!manifestProblem.empty() &&
        (anyFile || std::filesystem::exists(folder_ / kManifestName, ec))) {
        loadProblems_.push_back(manifestProblem);
    }
}

std::filesystem::path AutosaveStore::manifestPath() const {
    return folder_ / kManifestName;
}

void AutosaveStore::writeManifest() {
    const std::string text = toJson(manifest_).dump(2) + "\n";
    files::writeFileAtomically(manifestPath(), {std::as_bytes(std::span<const char>(text))});
}

std::filesystem::path AutosaveStore::save(AutosaveSnapshot snapshot) {
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec); // the write names the failure
    snapshot.sequence = nextSequence_++;
    const std::vector<std::byte> bytes = encodeSnapshot(snapshot);
    ManifestEntry entry;
    entry.file = fileNameFor(snapshot.sequence);
    entry.sequence = snapshot.sequence;
    entry.savedAtMs = snapshot.savedAtMs;
    entry.crc = snapshotCrc(bytes);
    entry.bytes = bytes.size();
    entry.state = std::string(model::stateName(snapshot.state));
    const std::filesystem::path path = folder_ / entry.file;
    files::writeFileAtomically(path, {std::span<const std::byte>(bytes)});
    manifest_.files.push_back(entry);
    manifest_.clean = false;
    std::vector<ManifestEntry> gone;
    while (manifest_.files.size() > keep_) {
        gone.push_back(manifest_.files.front());
        manifest_.files.erase(manifest_.files.begin());
    }
    writeManifest();
    // Only once the manifest no longer lists them.
    for (const ManifestEntry& e : gone) {
        std::filesystem::remove(folder_ / e.file, ec);
    }
    return path;
}

void AutosaveStore::markClean() {
    if (manifest_.files.empty()) {
        return;
    }
    manifest_.clean = true;
    writeManifest();
}

std::optional<AutosaveStore::Found>
AutosaveStore::newest(std::vector<std::string>& problems) const {
    problems.insert(problems.end(), loadProblems_.begin(), loadProblems_.end());
    std::vector<ManifestEntry> candidates = manifest_.files;
    if (!loadProblems_.empty()) {
        // No usable manifest: the folder's own files, by sequence (their names sort by it).
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(folder_, ec)) {
            const std::string name = entry.path().filename().string();
            if (isAutosaveName(name)) {
                candidates.push_back({name, 0, 0, 0, 0, ""});
            }
        }
        std::sort(candidates.begin(), candidates.end(),
                  [](const ManifestEntry& a, const ManifestEntry& b) { return a.file < b.file; });
    }
    for (auto it = candidates.rbegin(); it != candidates.rend(); ++it) {
        const std::filesystem::path path = folder_ / it->file;
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            problems.push_back(path.string() + ": listed in the manifest but missing");
            continue;
        }
        try {
            AutosaveSnapshot s = readSnapshotFile(path);
            if (it->bytes != 0) { // listed: it must be the file the manifest names
                const std::uint64_t size = std::filesystem::file_size(path, ec);
                if (size != it->bytes) {
                    throw AutosaveFormatError(path.string() + ": " + std::to_string(size) +
                                              " bytes, the manifest says " +
                                              std::to_string(it->bytes));
                }
                if (const std::uint32_t crc = headerCrc(path); crc != it->crc) {
                    throw AutosaveFormatError(path.string() + ": CRC32 " + std::to_string(crc) +
                                              ", the manifest says " + std::to_string(it->crc));
                }
                if (s.sequence != it->sequence) {
                    throw AutosaveFormatError(path.string() + ": sequence " +
                                              std::to_string(s.sequence) + ", the manifest says " +
                                              std::to_string(it->sequence));
                }
            }
            return Found{std::move(s), path, loadProblems_.empty() && manifest_.clean};
        } catch (const std::exception& e) {
            problems.emplace_back(e.what());
        }
    }
    return std::nullopt;
}

} // namespace steerseg::autosave
