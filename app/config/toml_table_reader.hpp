#pragma once

// Internal to config: typed reads of one TOML table. Each read records a problem (file, line,
// column, dotted key) for a wrong type or an out-of-range value and yields a value only when it
// is good; keys that no read asked for are reported as unknown.
#include "config/config_problem.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <toml++/toml.h>
#include <vector>

namespace steerseg::config::detail {

class ProblemSink {
  public:
    explicit ProblemSink(std::string file) : file_(std::move(file)) {}
    void add(const toml::source_region& where, std::string key, std::string message);
    [[nodiscard]] bool empty() const { return problems_.empty(); }
    // The problems, the last saying how many more there were past the cap (a hostile file
    // could otherwise fill the log with a line per key).
    std::vector<ConfigProblem> take();

  private:
    std::string file_;
    std::vector<ConfigProblem> problems_;
    std::size_t dropped_ = 0;
};

struct NumberRange {
    double min = 0.0;
    double max = 0.0;
    bool minExclusive = false; // (min, max] rather than [min, max]
};
struct IntRange {
    long long min = 0;
    long long max = 0;
};
// "" when the text is acceptable, else why not (without the key; the reader adds it).
using TextCheck = std::function<std::string(std::string_view)>;

// "display.rotation", "bindings.keys.\"ctrl+z\"": a key that is not bare is quoted as TOML does.
std::string keyPath(std::string_view prefix, std::string_view key);

// The same reads on a lone node (an array element), `key` naming it in problems.
std::optional<double> readNumber(const toml::node& node, const std::string& key,
                                 const NumberRange& range, ProblemSink& sink);
std::optional<std::string> readText(const toml::node& node, const std::string& key,
                                    const TextCheck& check, ProblemSink& sink);

class TableReader {
  public:
    TableReader(const toml::table& table, std::string prefix, ProblemSink& sink)
        : table_(table), prefix_(std::move(prefix)), sink_(sink) {}

    [[nodiscard]] bool has(std::string_view key) const { return table_.contains(key); }
    std::optional<long long> integer(std::string_view key, const IntRange& range);
    std::optional<double> number(std::string_view key, const NumberRange& range);
    std::optional<bool> boolean(std::string_view key);
    std::optional<std::string> text(std::string_view key, const TextCheck& check = {});
    // nullptr when absent, or when not a table / an array (reported).
    const toml::table* table(std::string_view key);
    const toml::array* array(std::string_view key);

    // A problem with `key`'s value that the typed reads cannot see (a choice, a relation).
    void problem(std::string_view key, std::string message);
    // Every key that no read above asked for, naming the ones the table has.
    void reportUnknownKeys();

    [[nodiscard]] std::string path(std::string_view key) const { return keyPath(prefix_, key); }
    [[nodiscard]] const toml::table& source() const { return table_; }
    ProblemSink& sink() { return sink_; }

  private:
    const toml::node* ask(std::string_view key);

    const toml::table& table_;
    std::string prefix_;
    ProblemSink& sink_;
    std::vector<std::string> known_;
};

} // namespace steerseg::config::detail
