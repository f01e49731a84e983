#pragma once

#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace steerseg::cli {

// A command-line mistake; main prints it with the command's usage and exits 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// `--name value` options (repeatable), `--flag` switches and positional words. Which names
// take values is declared up front so that a missing value is an error, not a swallowed flag.
class Args {
  public:
    Args(std::span<const std::string> words, const std::vector<std::string>& valueOptions,
         const std::vector<std::string>& flagOptions);

    [[nodiscard]] bool flag(const std::string& name) const;
    [[nodiscard]] std::optional<std::string> value(const std::string& name) const;
    [[nodiscard]] std::string required(const std::string& name) const;
    [[nodiscard]] std::vector<std::string> values(const std::string& name) const;
    [[nodiscard]] const std::vector<std::string>& positional() const { return positional_; }

    // Numbers with the option named in the error ("--eps: expected a number, got 'x'").
    [[nodiscard]] std::optional<double> number(const std::string& name) const;
    [[nodiscard]] std::optional<long long> integer(const std::string& name) const;

  private:
    std::map<std::string, std::vector<std::string>> values_;
    std::vector<std::string> flags_;
    std::vector<std::string> positional_;
};

// Strict parsers shared by commands: the whole text must be a finite number.
double parseNumber(const std::string& text, const std::string& what);
long long parseInteger(const std::string& text, const std::string& what);
// "a,b,c" -> numbers; `count` of them exactly.
// "WIDTHxHEIGHT" with each side in [minSide, maxSide]; UsageError naming `what` otherwise.
std::pair<int, int> parseSize(const std::string& text, const std::string& what, int minSide,
                              int maxSide);

std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what);

} // namespace steerseg::cli
