#include "scan/dicom/series.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

namespace steerseg::scan {

namespace {

struct Series {
    std::vector<DicomHeader> files;
};

bool sameSeries(const DicomHeader& a, const DicomHeader& b) {
    if (a.seriesUid != b.seriesUid || a.rows != b.rows || a.columns != b.columns || a.frames > 1 ||
        b.frames > 1 || a.orientation.has_value() != b.orientation.has_value()) {
        return false;
    }
    if (!a.orientation) {
        return true;
    }
    constexpr double kSameOrientation = 1e-4;
    return glm::length(a.orientation->first - b.orientation->first) < kSameOrientation &&
           glm::length(a.orientation->second - b.orientation->second) < kSameOrientation;
}

std::string listSeries(const std::vector<Series>& all) {
    std::string text;
    for (std::size_t s = 0; s < all.size(); ++s) {
        const DicomHeader& h = all[s].files.front();
        text += (s == 0 ? "" : "; ") + std::string("[") + std::to_string(s + 1) + "] " +
                (h.seriesUid.empty() ? std::string("(no SeriesInstanceUID)") : h.seriesUid) +
                " \"" + h.description + "\": ";
        if (h.frames > 1) {
            text += "one file of " + std::to_string(h.frames) + " frames (" +
                    h.file.filename().string() + ")";
        } else {
            text += std::to_string(all[s].files.size()) + " slice" +
                    (all[s].files.size() == 1 ? " (" + h.file.filename().string() + ")" : "s");
        }
        text += " of " + std::to_string(h.columns) + "x" + std::to_string(h.rows);
        if (h.orientation) {
            const auto& [r, c] = *h.orientation;
            char o[96];
            std::snprintf(o, sizeof o, ", orientation %.3g\\%.3g\\%.3g\\%.3g\\%.3g\\%.3g", r.x, r.y,
                          r.z, c.x, c.y, c.z);
            text += o;
        }
    }
    return text;
}

} // namespace

std::string describeNonImage(const DicomHeader& h) {
    std::string what = h.modality.empty() ? std::string("a DICOM object") : h.modality;
    if (!h.sopClassUid.empty()) {
        what += " (SOP class " + h.sopClassUid + ")";
    }
    return what;
}

DicomFolderScan scanDicomFolder(const std::filesystem::path& folder, const ReadLimits& limits) {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        std::error_code fileEc;
        if (entry.is_regular_file(fileEc)) {
            files.push_back(entry.path());
        }
    }
    if (ec) {
        throw ScanError(folder, "cannot list the folder: " + ec.message());
    }
    std::sort(files.begin(), files.end());
    DicomFolderScan scan;
    for (const auto& file : files) {
        if (!mightBeDicom(file)) {
            ++scan.notDicom;
            continue;
        }
        DicomHeader h = readDicomHeader(file, limits);
        if (h.isImage()) {
            scan.images.push_back(std::move(h));
        } else {
            scan.nonImage.push_back(describeNonImage(h));
        }
    }
    return scan;
}

std::vector<DicomHeader> selectSeries(const std::filesystem::path& folder, DicomFolderScan scan) {
    if (scan.images.empty()) {
        std::string problem = "no DICOM image in the folder";
        if (!scan.nonImage.empty()) {
            std::map<std::string, int> kinds;
            for (const auto& k : scan.nonImage) {
                ++kinds[k];
            }
            problem += " (it holds only";
            for (const auto& [kind, count] : kinds) {
                problem += " " + std::to_string(count) + "x " + kind;
            }
            problem += ", which have no pixel data)";
        }
        if (scan.notDicom > 0) {
            problem += "; " + std::to_string(scan.notDicom) + " non-DICOM files were skipped";
        }
        throw ScanError(folder, problem);
    }
    std::vector<Series> all;
    for (DicomHeader& h : scan.images) {
        const auto match = std::find_if(all.begin(), all.end(), [&](const Series& s) {
            return sameSeries(s.files.front(), h);
        });
        if (match == all.end()) {
            all.push_back(Series{{std::move(h)}});
        } else {
            match->files.push_back(std::move(h));
        }
    }
    if (all.size() > 1) {
        throw ScanError(folder, "the folder holds " + std::to_string(all.size()) +
                                    " image series and steerseg reads one; move each into its "
                                    "own folder: " +
                                    listSeries(all));
    }
    return std::move(all.front().files);
}

} // namespace steerseg::scan
