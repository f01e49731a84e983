#pragma once

// A recorded run's checks (tests/data/growth, written by segment_bench --growth-log): one line
// per check, iteration, evolved time, voxels gained, voxels lost, front voxels.
#include "solver/front_check.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace steerseg::test {

inline std::vector<solver::FrontCheck> frontSeries(const std::string& name) {
    const std::filesystem::path path = std::filesystem::path(STEERSEG_GROWTH_DATA_DIR) / name;
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot read " + path.string());
    }
    std::vector<solver::FrontCheck> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        std::istringstream fields(line);
        solver::FrontCheck c;
        fields >> c.iteration >> c.time >> c.gained >> c.lost >> c.front;
        if (!fields) {
            throw std::runtime_error("bad line in " + path.string() + ": " + line);
        }
        c.gainHi = {1, 1, 1};
        out.push_back(c);
    }
    return out;
}

} // namespace steerseg::test
