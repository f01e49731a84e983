#pragma once

// One autosave of an operator's session: which scan, the parameters, the sphere counts, the
// workflow state and the level set as a mask. On disk it is a fixed header (magic, version,
// sizes, CRC32 of the payload) and a payload of JSON metadata followed by the mask's runs, so a
// torn, truncated or bit-flipped file is recognised before anything in it is trusted.
#include "core/mask_runs.hpp"
#include "model/action.hpp"
#include "model/level_set_params.hpp"
#include "workflow/structures.hpp"
#include "workflow/undo_stack.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::autosave {

// Identifies the scan file so a resume refuses a different one under the same name: its size
// and modification time (a DICOM folder: its files' count and total size and newest time).
struct ScanReference {
    std::string path;
    std::uint64_t bytes = 0;
    std::int64_t mtimeNs = 0; // 0: not a file (the built-in sample)
    bool operator==(const ScanReference&) const = default;
};

// The reference of `path` as it is now (the built-in sample and missing paths: path only).
ScanReference referenceOf(const std::string& path);
// "" when `now` is the same file as `saved`, else one line saying what differs.
std::string differenceBetween(const ScanReference& saved, const ScanReference& now);

struct AutosaveSnapshot {
    ScanReference scan;
    glm::ivec3 dims{0};
    std::int64_t savedAtMs = 0; // UTC, milliseconds since the epoch
    std::uint64_t sequence = 0; // counts the session's autosaves
    model::State state = model::State::NoScan;
    workflow::ParamValues params;
    int seeds = 0;
    int erasures = 0;
    int iterations = 0;
    double evolvedTime = 0.0;
    MaskRuns mask; // no runs: no level set
    // The corrections that stick (kept and blocked spheres), in the order placed: without them a
    // resumed run would undo the operator's erases and let the kept spheres recede.
    std::vector<model::Barrier> barriers;
    // The session's structures (docs/structures.md): the active one's surface is `mask` and its
    // parameters `params`; the others' masks follow the active one's runs in the file. nullopt:
    // a session of one structure as a scan starts it (and every autosave from before them).
    std::optional<workflow::StructureList> structures;
};

class AutosaveFormatError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

inline constexpr std::uint32_t kAutosaveVersion = 1;

std::vector<std::byte> encodeSnapshot(const AutosaveSnapshot& snapshot);
// Throws AutosaveFormatError with one line: not an autosave (magic), another version, truncated
// or overlong, CRC mismatch, or metadata that does not fit the mask.
AutosaveSnapshot decodeSnapshot(std::span<const std::byte> bytes);
// The CRC32 (zlib's) a file of encodeSnapshot's carries in its header, for the manifest.
std::uint32_t snapshotCrc(std::span<const std::byte> encoded);

// Reads and decodes a file; AutosaveFormatError naming the file on any problem.
AutosaveSnapshot readSnapshotFile(const std::filesystem::path& path);

} // namespace steerseg::autosave
