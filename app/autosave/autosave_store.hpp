#pragma once

// The autosave folder: snapshots named by sequence (autosave-000042.ssav), the newest `keep`
// kept, and manifest.json listing them (file, time, CRC32, size, state) and whether the session
// that wrote them ended cleanly. Every file goes through files::writeFileAtomically, the manifest
// after the snapshot it names, so a crash at any point leaves either the old or the new list.
#include "autosave/autosave_snapshot.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace steerseg::autosave {

struct ManifestEntry {
    std::string file; // name inside the folder
    std::uint64_t sequence = 0;
    std::int64_t savedAtMs = 0;
    std::uint32_t crc = 0;
    std::uint64_t bytes = 0;
    std::string state;
    bool operator==(const ManifestEntry&) const = default;
};

struct Manifest {
    std::vector<ManifestEntry> files; // oldest first
    bool clean = false;               // the session ended (quit or exported); nothing to resume
};

class AutosaveStore {
  public:
    // Reads what the folder holds now (a missing folder is created on the first save).
    AutosaveStore(std::filesystem::path folder, int keep);

    // Writes the snapshot under the next sequence number, then the manifest, then removes the
    // files past `keep`. Returns the file written. Throws files::WriteError naming the file.
    std::filesystem::path save(AutosaveSnapshot snapshot);
    // The session ended cleanly: the manifest says so, and start-up offers no resume.
    void markClean();

    struct Found {
        AutosaveSnapshot snapshot;
        std::filesystem::path file;
        bool clean = false;
    };
    // The newest autosave that reads back whole. Each one passed over (missing, damaged, not
    // what the manifest says) and a damaged manifest add one line to `problems`.
    std::optional<Found> newest(std::vector<std::string>& problems) const;

    [[nodiscard]] const std::filesystem::path& folder() const { return folder_; }
    [[nodiscard]] const Manifest& manifest() const { return manifest_; }
    [[nodiscard]] std::filesystem::path manifestPath() const;

  private:
    void writeManifest();

    std::filesystem::path folder_;
    std::size_t keep_;
    Manifest manifest_;
    std::vector<std::string> loadProblems_;
    std::uint64_t nextSequence_ = 1;
};

// The manifest of `folder`; std::runtime_error with one line when it is missing or damaged.
Manifest readManifest(const std::filesystem::path& folder);

} // namespace steerseg::autosave
