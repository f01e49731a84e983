#include "script/script_tokens.hpp"

#include "script/script.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace steerseg::script::detail {

namespace {

// Long words are cut in messages so one bad line stays one readable line.
std::string quoteWord(std::string_view word) {
    constexpr std::size_t kShown = 40;
    if (word.size() > kShown) {
        return "'" + std::string(word.substr(0, kShown)) + "...'";
    }
    return "'" + std::string(word) + "'";
}

bool isNameChar(char c, bool first) {
    return (c >= 'A' && c <= 'Z') || c == '_' || (!first && c >= '0' && c <= '9');
}

} // namespace

std::vector<std::string> splitWords(std::string_view line) {
    std::vector<std::string> words;
    std::size_t n = 0;
    while (n < line.size()) {
        const char c = line[n];
        if (c == ' ' || c == '\t') {
            ++n;
            continue;
        }
        if (c == '#') {
            break;
        }
        std::string word;
        if (c == '"') {
            ++n;
            bool closed = false;
            while (n < line.size()) {
                const char q = line[n++];
                if (q == '"') {
                    closed = true;
                    break;
                }
                if (q == '\\' && n < line.size() && (line[n] == '"' || line[n] == '\\')) {
                    word += line[n++];
                    continue;
                }
                word += q;
            }
            if (!closed) {
                throw LineError("a quote is not closed");
            }
        } else {
            while (n < line.size() && line[n] != ' ' && line[n] != '\t' && line[n] != '#') {
                word += line[n++];
            }
        }
        words.push_back(std::move(word));
    }
    return words;
}

std::string_view withoutComment(std::string_view line) {
    bool quoted = false;
    for (std::size_t n = 0; n < line.size(); ++n) {
        if (quoted && line[n] == '\\') {
            ++n;
        } else if (line[n] == '"') {
            quoted = !quoted;
        } else if (!quoted && line[n] == '#') {
            return line.substr(0, n);
        }
    }
    return line;
}

std::string Words::text(const char* what) {
    if (empty()) {
        throw LineError(std::string("missing ") + what);
    }
    return words_[at_++];
}

double Words::number(const char* what, double min, double max) {
    const std::string word = text(what);
    double value = 0.0;
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, value);
    if (ec == std::errc::result_out_of_range) {
        throw LineError(std::string(what) + " " + quoteWord(word) + " is out of range");
    }
    if (ec != std::errc() || ptr != end) {
        throw LineError(std::string(what) + " must be a number, not " + quoteWord(word));
    }
    if (!std::isfinite(value)) {
        throw LineError(std::string(what) + " must be a finite number, not " + quoteWord(word));
    }
    if (value < min || value > max) {
        char range[96];
        std::snprintf(range, sizeof range, " is outside [%g, %g]", min, max);
        throw LineError(std::string(what) + " " + quoteWord(word) + range);
    }
    return value;
}

long long Words::integer(const char* what, long long min, long long max) {
    const std::string word = text(what);
    long long value = 0;
    const char* begin = word.data() + (word.starts_with('+') ? 1 : 0);
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec == std::errc::result_out_of_range) {
        throw LineError(std::string(what) + " " + quoteWord(word) + " is out of range");
    }
    if (ec != std::errc() || ptr != end) {
        throw LineError(std::string(what) + " must be a whole number, not " + quoteWord(word));
    }
    if (value < min || value > max) {
        throw LineError(std::string(what) + " " + quoteWord(word) + " is outside [" +
                        std::to_string(min) + ", " + std::to_string(max) + "]");
    }
    return value;
}

bool Words::accept(std::string_view word) {
    if (!empty() && words_[at_] == word) {
        ++at_;
        return true;
    }
    return false;
}

void Words::finish(const char* usage) const {
    if (!empty()) {
        throw LineError("unexpected " + quoteWord(words_[at_]) + " (usage: " + usage + ")");
    }
}

void checkVariables(std::string_view word) {
    const auto& known = scriptVariables();
    for (std::size_t n = 0; n < word.size(); ++n) {
        if (word[n] != '$') {
            continue;
        }
        const bool braced = n + 1 < word.size() && word[n + 1] == '{';
        std::size_t begin = n + (braced ? 2 : 1);
        std::size_t end = begin;
        while (end < word.size() && isNameChar(word[end], end == begin)) {
            ++end;
        }
        if (braced && (end >= word.size() || word[end] != '}')) {
            throw LineError("a ${ in " + quoteWord(word) + " is not closed by }");
        }
        const std::string_view name = word.substr(begin, end - begin);
        if (name.empty()) {
            throw LineError(
                "a $ in " + quoteWord(word) +
                " names no variable (SCAN, DATA, OUT, EXPORTED, RECEIVED, FOUND, SERIES)");
        }
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            throw LineError("unknown variable $" + std::string(name) +
                            " (known: SCAN, DATA, OUT, EXPORTED, RECEIVED, FOUND, SERIES)");
        }
        n = end;
    }
}

} // namespace steerseg::script::detail
