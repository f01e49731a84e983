#include "net/received_series.hpp"

#include "net/series_marks.hpp"
#include "net/store_scp.hpp" // isSafeUid
#include "scan/series_state.hpp"

#include <algorithm>
#include <dcmtk/config/osconfig.h> // must come first among DCMTK's headers
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <optional>

namespace steerseg::net {
namespace {

namespace fs = std::filesystem;

std::string tagText(DcmDataset& dataset, const DcmTagKey& tag) {
    OFString value;
    dataset.findAndGetOFString(tag, value);
    return value.c_str();
}

std::string dateText(const std::string& da) {
    const bool dicomDate = da.size() == 8 && std::all_of(da.begin(), da.end(), [](char c) {
                               return c >= '0' && c <= '9';
                           });
    return dicomDate ? da.substr(0, 4) + "-" + da.substr(4, 2) + "-" + da.substr(6, 2) : da;
}

// Printable ASCII only: a header's bytes are the peer's, the label is drawn on the panel.
std::string printable(std::string text) {
    std::replace(text.begin(), text.end(), '^', ' ');
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c < ' ' || c > '~'; }, '?');
    while (!text.empty() && text.back() == ' ') {
        text.pop_back();
    }
    return text;
}

// The header of the first file that reads as DICOM (the pixel data is never read).
bool readHeader(const std::vector<fs::path>& files, ReceivedSeries& series) {
    for (const fs::path& file : files) {
        DcmFileFormat format;
        if (format
                .loadFileUntilTag(file.c_str(), EXS_Unknown, EGL_noChange, DCM_MaxReadLength,
                                  ERM_autoDetect, DCM_PixelData)
                .bad()) {
            continue;
        }
        DcmDataset& d = *format.getDataset();
        series.patient = printable(tagText(d, DCM_PatientName));
        series.studyDate = printable(dateText(tagText(d, DCM_StudyDate)));
        series.modality = printable(tagText(d, DCM_Modality));
        series.description = printable(tagText(d, DCM_SeriesDescription));
        if (series.description.empty()) {
            series.description = printable(tagText(d, DCM_StudyDescription));
        }
        return true;
    }
    return false;
}

std::optional<ReceivedSeries> readSeries(const fs::path& folder) {
    ReceivedSeries series;
    series.folder = folder;
    // Not the clock's epoch, which libstdc++ puts in 2174.
    series.newest = fs::file_time_type::min();
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(folder, ec)) {
        const fs::path& path = item.path();
        if (path.filename().string().front() == '.' || path.extension() != ".dcm" ||
            !item.is_regular_file(ec)) {
            continue;
        }
        const auto written = item.last_write_time(ec);
        if (ec) {
            continue; // removed meanwhile (retention)
        }
        series.newest = std::max(series.newest, written);
        files.push_back(path);
    }
    if (files.empty()) {
        return std::nullopt;
    }
    series.images = static_cast<int>(files.size());
    // The same file each time, so a listing does not change with the directory's order.
    std::sort(files.begin(), files.end());
    if (!readHeader(files, series)) {
        return std::nullopt;
    }
    return series;
}

std::vector<fs::path> uidFolders(const fs::path& parent) {
    std::vector<fs::path> folders;
    std::error_code ec;
    for (const auto& item : fs::directory_iterator(parent, ec)) {
        if (isSafeUid(item.path().filename().string()) && item.is_directory(ec)) {
            folders.push_back(item.path());
        }
    }
    return folders;
}

} // namespace

std::vector<ReceivedSeries> listReceivedSeries(const fs::path& store, std::chrono::seconds settle,
                                               fs::file_time_type now) {
    std::vector<ReceivedSeries> list;
    for (const fs::path& study : uidFolders(store)) {
        for (const fs::path& folder : uidFolders(study)) {
            if (auto series = readSeries(folder)) {
                const scan::SeriesState state = scan::seriesState(folder);
                series->arriving = now - series->newest < settle || state.receiving;
                series->incomplete = state.incomplete;
                list.push_back(std::move(*series));
            }
        }
    }
    std::sort(list.begin(), list.end(), [](const ReceivedSeries& a, const ReceivedSeries& b) {
        return std::tie(b.newest, b.folder) < std::tie(a.newest, a.folder);
    });
    return list;
}

std::string describe(const ReceivedSeries& s) {
    std::string line;
    for (const std::string* part : {&s.modality, &s.studyDate, &s.patient}) {
        if (!part->empty()) {
            line += (line.empty() ? "" : " ") + *part;
        }
    }
    if (!s.description.empty()) {
        line += (line.empty() ? "" : ", ") + s.description;
    }
    line += (line.empty() ? "(" : " (") + std::to_string(s.images) +
            (s.images == 1 ? " image)" : " images)");
    if (s.arriving) {
        return line + " - arriving";
    }
    return s.incomplete ? line + " - incomplete (sending ended early)" : line;
}

} // namespace steerseg::net
