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

} // namespace steerseg::autosave
