#pragma once

// The series in the incoming store (<store>/<study UID>/<series UID>/<instance>.dcm, as the
// Storage SCP files them), as the kiosk's load screen lists them: who and what each is, how many
// images have come, and whether more may still be coming. GL-free; reads only the headers of
// one file per series.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace steerseg::net {

struct ReceivedSeries {
    std::filesystem::path folder; // <store>/<study>/<series>: what LoadScan opens
    std::string patient;          // PatientName, "^" as blanks ("" when the header has none)
    std::string studyDate;        // YYYY-MM-DD, or as written when it is no DICOM date
    std::string modality;         // "CT", "MR", ...
    std::string description;      // SeriesDescription, else StudyDescription
    int images = 0;               // files of the series (one instance each)
    // A file came within the settle time, or an association writing into it is still open:
    // more may follow.
    bool arriving = false;
    // An association (or a C-GET) that wrote into it ended before it was done (aborted, cut
    // off, timed out, the node stopped or killed; series_marks), and no complete send has come
    // since: images may be missing, so it must not be loaded as if whole.
    bool incomplete = false;
    std::filesystem::file_time_type newest; // the newest file's time
};

// The store's series, newest first. A series whose newest file is younger than `settle` (at
// `now`), or that an open association is writing into, is still arriving; one that an
// association left unfinished is incomplete. Folders that are not a UID pair, hidden files (a
// write's temporary) and files that are no DICOM are passed over, never thrown for: a listing of a
// store being written or pruned shows what it can.
std::vector<ReceivedSeries> listReceivedSeries(
    const std::filesystem::path& store, std::chrono::seconds settle,
    std::filesystem::file_time_type now = std::filesystem::file_time_type::clock::now());

// One line for a button: "CT 2026-11-20 Doe John, Chest 1.0 (60 images)", " - arriving" added
// while it is, else " - incomplete (sending ended early)" when it is.
std::string describe(const ReceivedSeries& series);

} // namespace steerseg::net
