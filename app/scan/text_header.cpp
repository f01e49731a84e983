#include "scan/text_header.hpp"

#include "scan/byte_source.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>

namespace steerseg::scan {

std::string readHeaderPrefix(SeekableSource& file) {
    file.seek(0);
    const std::vector<std::byte> bytes = readUpTo(file, kMaxTextHeaderBytes);
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

std::optional<HeaderLine> nextLine(std::string_view text, std::size_t from) {
    if (from >= text.size()) {
        return std::nullopt;
    }
    const std::size_t end = text.find('\n', from);
    HeaderLine line;
    if (end == std::string_view::npos) {
        line.text = text.substr(from);
        line.next = text.size();
    } else {
        line.text = text.substr(from, end - from);
        line.next = end + 1;
    }
    if (!line.text.empty() && line.text.back() == '\r') {
        line.text.remove_suffix(1);
    }
    return line;
}

std::string_view trim(std::string_view s) {
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (!s.empty() && space(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && space(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

std::string toLower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::optional<std::vector<double>> parseNumbers(std::string_view s, bool commas) {
    std::vector<double> out;
    const char* p = s.data();
    const char* end = s.data() + s.size();
    const auto separator = [&](char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || (commas && c == ',');
    };
    while (true) {
        while (p < end && separator(*p)) {
            ++p;
        }
        if (p == end) {
            return out;
        }
        if (*p == '+') {
            ++p; // from_chars does not take a leading '+', which some writers print
        }
        double v = 0.0;
        const auto [next, ec] = std::from_chars(p, end, v);
        if (ec != std::errc{} || (next < end && !separator(*next))) {
            return std::nullopt;
        }
        out.push_back(v);
        p = next;
    }
}

std::optional<std::int64_t> parseInteger(std::string_view s, std::int64_t lo, std::int64_t hi) {
    s = trim(s);
    if (!s.empty() && s.front() == '+') {
        s.remove_prefix(1);
    }
    std::int64_t v = 0;
    const auto [next, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc{} || next != s.data() + s.size() || v < lo || v > hi) {
        return std::nullopt;
    }
    return v;
}

int axisLength(double v) {
    if (!std::isfinite(v) || v != std::floor(v)) {
        return -1;
    }
    return v >= static_cast<double>(INT_MAX) ? INT_MAX : static_cast<int>(std::max(v, -1.0));
}

} // namespace steerseg::scan
