#pragma once

// File-name tests shared by the reader dispatch and the writers: formats are chosen by
// case-insensitive suffix ("scan.NII.GZ" is NIfTI).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace steerseg::model {

inline std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// The file name (not the folder), lower-cased.
inline std::string lowerFileName(const std::filesystem::path& path) {
    return lowerCase(path.filename().string());
}

inline bool hasSuffix(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace steerseg::model
