#pragma once

// Whether a DICOM series folder is whole, as the node's marks say (net/series_marks writes
// them; docs/dicom-network.md, "Whole or incomplete"). Here, below the node, so that every
// reader of a folder (the kiosk's load, a script's, the command line's) refuses a series an
// association left unfinished instead of loading it as if whole.
#include <filesystem>
#include <vector>

namespace steerseg::scan {

// A series folder's mark files begin with this.
inline constexpr const char* kReceivingMarkPrefix = ".receiving-";

// What the marks in `folder` say: `incomplete` when a dead one is there (its writer ended
// without finishing), `receiving` when an open association holds one (its lock is held).
struct SeriesState {
    bool incomplete = false;
    bool receiving = false;
};
SeriesState seriesState(const std::filesystem::path& folder);
// The dead marks in `folder`: those a later whole send of the series takes away.
std::vector<std::filesystem::path> deadSeriesMarks(const std::filesystem::path& folder);

} // namespace steerseg::scan
