#include "platform/input/recording.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>

namespace steerseg::platform::input {

namespace {

constexpr std::size_t kMaxLineBytes = 16 * 1024;
constexpr std::size_t kMaxPayloadBytes = 4096;
constexpr std::size_t kMaxNameChars = 64;
constexpr double kMaxTime = 1e9; // seconds: about 31 years of recording
constexpr std::size_t kMaxProblems = 100;
constexpr std::string_view kHeader = "# steerseg input recording ";

// A token quoted in a problem line, cut so a garbage line cannot make a huge message.
std::string quoted(std::string_view token) {
    constexpr std::size_t kShown = 32;
    std::string q = "'" + std::string(token.substr(0, kShown));
    return q + (token.size() > kShown ? "...'" : "'");
}

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

std::vector<std::string_view> splitFields(std::string_view line, std::size_t maxFields) {
    std::vector<std::string_view> fields;
    std::size_t i = 0;
    while (i < line.size() && fields.size() <= maxFields) {
        while (i < line.size() && isBlank(line[i])) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) {
            ++i;
        }
        if (i > start) {
            fields.push_back(line.substr(start, i - start));
        }
    }
    return fields;
}

template <typename T> bool parseNumber(std::string_view text, T& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && ptr == end;
}

bool isControlName(std::string_view name) {
    if (name.empty() || name.size() > kMaxNameChars) {
        return false;
    }
    for (const char c : name) {
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) {
            return false;
        }
    }
    return true;
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F') {
        return c - 'A' + 10;
    }
    return -1;
}

bool parseHex(std::string_view text, std::vector<std::uint8_t>& bytes, std::string& problem) {
    if (text.size() % 2 != 0) {
        problem = "odd number of hex digits in " + quoted(text);
        return false;
    }
    if (text.size() / 2 > kMaxPayloadBytes) {
        problem = std::to_string(text.size() / 2) + " bytes, over the " +
                  std::to_string(kMaxPayloadBytes) + "-byte limit";
        return false;
    }
    bytes.resize(text.size() / 2);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const int hi = hexDigit(text[2 * i]);
        const int lo = hexDigit(text[2 * i + 1]);
        if (hi < 0 || lo < 0) {
            problem = "not hex: " + quoted(text);
            return false;
        }
        bytes[i] = static_cast<std::uint8_t>(hi * 16 + lo);
    }
    return true;
}

bool wantFields(const std::vector<std::string_view>& f, std::size_t count, std::string_view kind,
                std::string_view what, std::string& problem) {
    if (f.size() != 3 + count) {
        problem = std::string(kind) + " takes " + std::string(what);
        return false;
    }
    return true;
}

bool parsePayload(const std::vector<std::string_view>& f, RawRecord& r, std::string& problem) {
    const std::string_view kind = f[2];
    if (kind == "hid-descriptor" || kind == "hid") {
        r.kind = kind == "hid" ? RawRecord::Kind::HidReport : RawRecord::Kind::HidDescriptor;
        if (!wantFields(f, 1, kind, "one hex field", problem)) {
            return false;
        }
        if (!parseHex(f[3], r.bytes, problem)) {
            return false;
        }
        return true;
    }
    if (kind == "evdev") {
        r.kind = RawRecord::Kind::Evdev;
        if (!wantFields(f, 3, kind, "type, code and value (decimal)", problem)) {
            return false;
        }
        if (!parseNumber(f[3], r.type) || !parseNumber(f[4], r.code) ||
            !parseNumber(f[5], r.value)) {
            problem = "evdev type, code and value must be decimal (0..65535, 0..65535, int32)";
            return false;
        }
        return true;
    }
    if (kind == "gpio") {
        r.kind = RawRecord::Kind::GpioEdge;
        if (!wantFields(f, 1, kind, "1 or 0", problem)) {
            return false;
        }
        if (f[3] != "0" && f[3] != "1") {
            problem = "gpio takes 1 or 0, not " + quoted(f[3]);
            return false;
        }
        r.active = f[3] == "1";
        return true;
    }
    if (kind == "unplug" || kind == "plug") {
        r.kind = kind == "plug" ? RawRecord::Kind::Plugged : RawRecord::Kind::Unplugged;
        return wantFields(f, 0, kind, "nothing after it", problem);
    }
    problem =
        "unknown record kind " + quoted(kind) + " (hid-descriptor, hid, evdev, gpio, unplug, plug)";
    return false;
}

std::string hex(const std::vector<std::uint8_t>& bytes) {
    static constexpr std::array<char, 16> kDigits{'0', '1', '2', '3', '4', '5', '6', '7',
                                                  '8', '9', 'a', 'b', 'c', 'd', 'e', 'f'};
    std::string text;
    text.reserve(2 * bytes.size());
    for (const std::uint8_t b : bytes) {
        text += kDigits[b >> 4];
        text += kDigits[b & 15U];
    }
    return text;
}

// Reads one line of at most kMaxLineBytes into `line`; a longer one is read to its end and
// flagged, so a file without newlines costs no more memory than one line.
bool readLine(std::streambuf& in, std::string& line, bool& tooLong) {
    line.clear();
    tooLong = false;
    int c = in.sbumpc();
    if (c == std::char_traits<char>::eof()) {
        return false;
    }
    while (c != std::char_traits<char>::eof() && c != '\n') {
        if (line.size() < kMaxLineBytes) {
            line += static_cast<char>(c);
        } else {
            tooLong = true;
        }
        c = in.sbumpc();
    }
    return true;
}

} // namespace

std::optional<RawRecord> parseRecordLine(std::string_view line, std::string& problem) {
    problem.clear();
    if (line.size() > kMaxLineBytes) {
        problem = "line over 16 KiB";
        return std::nullopt;
    }
    if (!line.empty() && line.back() == '\r') {
        line.remove_suffix(1);
    }
    std::size_t first = 0;
    while (first < line.size() && isBlank(line[first])) {
        ++first;
    }
    line.remove_prefix(first);
    if (line.empty()) {
        return std::nullopt;
    }
    if (line.front() == '#') {
        if (line.starts_with(kHeader) && line.substr(kHeader.size()) != "1") {
            problem = "recording format " + quoted(line.substr(kHeader.size())) +
                      ", this build reads format 1";
        }
        return std::nullopt;
    }
    constexpr std::size_t kMostFields = 6;
    const std::vector<std::string_view> f = splitFields(line, kMostFields);
    if (f.size() < 3) {
        problem = "expected TIME DEVICE KIND ...";
        return std::nullopt;
    }
    RawRecord r;
    if (!parseNumber(f[0], r.time) || !std::isfinite(r.time) || std::signbit(r.time) ||
        r.time >= kMaxTime) {
        problem = "time " + quoted(f[0]) + " is not seconds from the start";
        return std::nullopt;
    }
    if (!isControlName(f[1])) {
        problem = "device " + quoted(f[1]) + " is not a name of a-z, 0-9, _ (at most 64)";
        return std::nullopt;
    }
    r.device = std::string(f[1]);
    if (!parsePayload(f, r, problem)) {
        return std::nullopt;
    }
    return r;
}

std::string formatRecordLine(const RawRecord& record) {
    std::array<char, 64> time{};
    std::snprintf(time.data(), time.size(), "%.6f", record.time);
    std::string line = std::string(time.data()) + " " + record.device + " ";
    switch (record.kind) {
    case RawRecord::Kind::HidDescriptor:
        return line + "hid-descriptor " + hex(record.bytes);
    case RawRecord::Kind::HidReport:
        return line + "hid " + hex(record.bytes);
    case RawRecord::Kind::Evdev:
        return line + "evdev " + std::to_string(record.type) + " " + std::to_string(record.code) +
               " " + std::to_string(record.value);
    case RawRecord::Kind::GpioEdge:
        return line + "gpio " + (record.active ? "1" : "0");
    case RawRecord::Kind::Unplugged:
        return line + "unplug";
    case RawRecord::Kind::Plugged:
        return line + "plug";
    }
    return line;
}

Recording parseRecording(std::istream& in, const std::string& name, std::size_t maxRecords) {
    Recording out;
    std::size_t moreProblems = 0;
    const auto problem = [&](std::size_t lineNo, const std::string& text) {
        if (out.problems.size() < kMaxProblems) {
            out.problems.push_back(name + ":" + std::to_string(lineNo) + ": " + text);
        } else {
            ++moreProblems;
        }
    };
    std::streambuf* buffer = in.rdbuf();
    std::string line;
    std::string why;
    bool tooLong = false;
    double lastTime = 0.0;
    for (std::size_t lineNo = 1; buffer && readLine(*buffer, line, tooLong); ++lineNo) {
        if (tooLong) {
            problem(lineNo, "line over 16 KiB (skipped)");
            continue;
        }
        std::optional<RawRecord> record = parseRecordLine(line, why);
        if (!record) {
            if (!why.empty()) {
                problem(lineNo, why);
            }
            continue;
        }
        if (record->time < lastTime) {
            problem(lineNo, "time goes back before the previous line's (skipped)");
            continue;
        }
        if (out.records.size() >= maxRecords) {
            problem(lineNo, "over " + std::to_string(maxRecords) +
                                " records: this line and the rest dropped");
            break;
        }
        lastTime = record->time;
        out.records.push_back(std::move(*record));
    }
    if (moreProblems > 0) {
        out.problems.push_back(name + ": ... and " + std::to_string(moreProblems) +
                               " more problems");
    }
    return out;
}

Recording readRecording(const std::string& path, std::size_t maxRecords) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        return {{}, {path + ": is a folder, not a recording"}};
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return {{}, {path + ": cannot open: " + std::strerror(errno)}};
    }
    return parseRecording(file, path, maxRecords);
}

} // namespace steerseg::platform::input
