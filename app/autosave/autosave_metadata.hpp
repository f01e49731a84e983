#pragma once

// The JSON metadata of an autosave (autosave_metadata.cpp), inside the snapshot's framing
// (autosave_snapshot.cpp).
#include "autosave/autosave_snapshot.hpp"

#include <nlohmann/json.hpp>

namespace steerseg::autosave {

// Everything of the snapshot but its mask.
nlohmann::json metadata(const AutosaveSnapshot& snapshot);
// Fills everything of `snapshot` but its mask; AutosaveFormatError (or nlohmann's exceptions)
// for metadata no session could have written.
void readMetadata(const nlohmann::json& j, AutosaveSnapshot& snapshot);
// How many runs each structure's mask has in the file after the active one's (0 for the active
// one), in order; none for a snapshot without structures.
std::vector<std::uint64_t> structureRunCounts(const nlohmann::json& j);

} // namespace steerseg::autosave
