#pragma once

// Whether a received series is whole (issue 48). DICOM does not say how many images a series
// has, so the node says which series an association left unfinished: before its first object
// lands in a series folder, the association writes a mark there (<series>/.receiving-<id>,
// durably, and holds an advisory lock on it while it is open). An association that ends with
// its release and every object stored removes its marks, and the marks that were already dead
// when it began writing there (a later complete send makes the series whole again). One that
// ends any other way (aborted by the peer, a reset connection, a timeout, the node stopped, the
// process killed) leaves them: its series is incomplete, across restarts, until a complete send.
// A mark whose lock is held belongs to an association still open; one nobody holds is dead
// (scan/series_state reads them).
#include "scan/series_state.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace steerseg::net {

// The marks one association (or one retrieve) holds.
class SeriesMarks {
  public:
    explicit SeriesMarks(std::string who); // "AE at address": written into each mark
    ~SeriesMarks();                        // finish(false) when not finished
    SeriesMarks(const SeriesMarks&) = delete;
    SeriesMarks& operator=(const SeriesMarks&) = delete;

    // Before an object is written into `folder` (which exists): its mark, once per folder.
    // "" when it is there, else why not in one line (the object must then be refused: a series
    // that could end half sent must not look whole).
    std::string mark(const std::filesystem::path& folder);
    // `whole`: the sender released the association and every object was stored; the marks go.
    // Otherwise they stay. Returns the folders marked, for the report.
    std::vector<std::filesystem::path> finish(bool whole);

  private:
    struct Mark {
        std::filesystem::path folder;
        std::filesystem::path file;
        int fd = -1;                              // holds the lock
        std::vector<std::filesystem::path> stale; // dead marks there when this one was made
    };
    std::string who_;
    std::vector<Mark> marks_;
    bool finished_ = false;
};

} // namespace steerseg::net
