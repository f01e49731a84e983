#pragma once

// The problems a decoder collects between two takeProblems() calls, bounded: a device that
// floods garbage must not grow memory, so past `kept` lines only a count is kept and the last
// line says "... and N more".
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::platform::input {

class ProblemLog {
  public:
    explicit ProblemLog(std::size_t kept = 32) : kept_(kept) {}

    void add(std::string line) {
        if (lines_.size() < kept_) {
            lines_.push_back(std::move(line));
        } else {
            ++dropped_;
        }
    }

    std::vector<std::string> take() {
        std::vector<std::string> out = std::move(lines_);
        lines_.clear();
        if (dropped_ > 0) {
            out.push_back("... and " + std::to_string(dropped_) + " more");
            dropped_ = 0;
        }
        return out;
    }

  private:
    std::size_t kept_;
    std::vector<std::string> lines_;
    std::size_t dropped_ = 0;
};

} // namespace steerseg::platform::input
