#pragma once

// A DICOM SR Measurement Report read back by an independent reader (pydicom,
// tests/tools/read_measurement_report.py): what the report and structure tests compare with
// `steerseg measure`.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace steerseg::test {

// A program's output as tab-separated words per line, by their first word.
std::multimap<std::string, std::vector<std::string>> wordsByLine(const std::string& output);

// The reader's tab-separated words per line, by their first word ("header", "group", "num",
// "observer").
std::multimap<std::string, std::vector<std::string>>
readReport(const std::filesystem::path& report);

// The NUM items of group `group`, by "code derivation" ("118565006 -", "112031 373098007"):
// unit, DS value, floating point value.
struct Num {
    std::string unit;
    double ds = 0.0;
    double fp = 0.0;
};
std::map<std::string, Num> numsOf(const std::multimap<std::string, std::vector<std::string>>& r,
                                  const std::string& group);

} // namespace steerseg::test
