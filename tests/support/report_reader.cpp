#include "support/report_reader.hpp"

#include "support/cli_run.hpp"

#include <gtest/gtest.h>
#include <sstream>

namespace steerseg::test {

std::multimap<std::string, std::vector<std::string>> wordsByLine(const std::string& output) {
    std::multimap<std::string, std::vector<std::string>> out;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> words;
        std::istringstream in(line);
        for (std::string w; std::getline(in, w, '\t');) {
            words.push_back(w);
        }
        if (!words.empty()) {
            const std::string key = words.front();
            words.erase(words.begin());
            out.emplace(key, words);
        }
    }
    return out;
}

std::multimap<std::string, std::vector<std::string>>
readReport(const std::filesystem::path& report) {
    const ShellRun r = runShell("/usr/bin/python3 " +
                                shellQuoted(std::filesystem::path(STEERSEG_DEFAULT_SOURCE_DIR) /
                                            "tests" / "tools" / "read_measurement_report.py") +
                                " " + shellQuoted(report));
    EXPECT_EQ(r.status, 0) << r.output;
    return wordsByLine(r.output);
}

std::map<std::string, Num> numsOf(const std::multimap<std::string, std::vector<std::string>>& r,
                                  const std::string& group) {
    std::map<std::string, Num> out;
    const auto [from, to] = r.equal_range("num");
    for (auto it = from; it != to; ++it) {
        const std::vector<std::string>& w = it->second; // N code scheme unit derivation ds fp
        if (w.size() == 7 && w[0] == group) {
            out[w[1] + " " + w[4]] = {w[3], std::stod(w[5]), std::stod(w[6])};
        }
    }
    return out;
}

} // namespace steerseg::test
