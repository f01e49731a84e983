#include "config/config_problem.hpp"

#include <cstdio>

namespace steerseg::config {

namespace {

// A key or a parser message may hold a newline or an escape from the file ("a\nb" = 1 is a
// valid TOML key); the report stays one line whatever the file holds.
void appendPrintable(std::string& out, const std::string& text) {
    for (const char ch : text) {
        const auto byte = static_cast<unsigned char>(ch);
        if (byte < 0x20 || byte == 0x7f) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned>(byte));
            out += escaped;
        } else {
            out += ch;
        }
    }
}

} // namespace

std::string describe(const ConfigProblem& problem) {
    std::string out;
    appendPrintable(out, problem.file);
    if (problem.line > 0) {
        out += ':' + std::to_string(problem.line) + ':' + std::to_string(problem.column);
    }
    out += ": ";
    if (!problem.key.empty()) {
        appendPrintable(out, problem.key);
        out += ": ";
    }
    appendPrintable(out, problem.message);
    return out;
}

} // namespace steerseg::config
