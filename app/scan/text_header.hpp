#pragma once

// Pieces shared by the text-header formats (NRRD, MetaImage): reading the header text, splitting
// lines and parsing number lists. Everything works on in-memory strings so that tests and fuzz
// targets can call the parsers directly.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::scan {

class SeekableSource;

// Text headers are small (a few KiB, even with DWI gradient tables); a file whose header does
// not end within this many bytes is refused rather than searched further.
inline constexpr std::size_t kMaxTextHeaderBytes = 1024 * 1024;

// The first kMaxTextHeaderBytes of `file` (all of it if shorter), from the start.
std::string readHeaderPrefix(SeekableSource& file);

// One header line: its text without the line end, and the offset just past its line end.
struct HeaderLine {
    std::string_view text;
    std::size_t next = 0;
};

// Splits `text` at '\n' (dropping a trailing '\r'), starting at `from`; nullopt at the end.
std::optional<HeaderLine> nextLine(std::string_view text, std::size_t from);

std::string_view trim(std::string_view s);
std::string toLower(std::string_view s);

// Numbers separated by white space (and commas where `commas`); nullopt if any is malformed.
// "nan" parses (NRRD writes it for unknown spacings).
std::optional<std::vector<double>> parseNumbers(std::string_view s, bool commas = false);

// A whole integer in [lo, hi]; nullopt otherwise.
std::optional<std::int64_t> parseInteger(std::string_view s, std::int64_t lo, std::int64_t hi);

// An axis length read as a number: itself if whole, INT_MAX past it (refused later by
// checkDims), -1 if not a whole number.
int axisLength(double v);

} // namespace steerseg::scan
