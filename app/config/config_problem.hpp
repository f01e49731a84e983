#pragma once

#include <string>

namespace steerseg::config {

// One thing wrong with a configuration file. line and column are 1-based; 0 where the problem
// concerns the whole file (missing, too large). key is the dotted key ("display.rotation"),
// empty where there is none (a syntax error).
struct ConfigProblem {
    std::string file;
    int line = 0;
    int column = 0;
    std::string key;
    std::string message;
};

// "FILE:LINE:COL: KEY: problem" on one line (control characters escaped), leaving out the
// position or the key where there is none.
std::string describe(const ConfigProblem& problem);

} // namespace steerseg::config
