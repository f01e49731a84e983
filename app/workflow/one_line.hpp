#pragma once

// Engines and readers throw one line for the operator; a stray newline must not break the
// panel or the audit record.
#include <string>

namespace steerseg::workflow {

inline std::string oneLine(const char* what) {
    std::string s = what != nullptr ? what : "";
    const auto nl = s.find_first_of("\r\n");
    if (nl != std::string::npos) {
        s.resize(nl);
    }
    return s.empty() ? std::string("unexpected failure") : s;
}

} // namespace steerseg::workflow
