#include "config/toml_table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace steerseg::config::detail {

namespace {

constexpr std::size_t kMaxProblems = 100;
constexpr std::size_t kMaxTextBytes = 4096;

std::string typeName(toml::node_type type) {
    switch (type) {
    case toml::node_type::table:
        return "a table";
    case toml::node_type::array:
        return "an array";
    case toml::node_type::string:
        return "a string";
    case toml::node_type::integer:
        return "an integer";
    case toml::node_type::floating_point:
        return "a floating-point number";
    case toml::node_type::boolean:
        return "a boolean";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time:
        return "a date or time";
    case toml::node_type::none:
        break;
    }
    return "nothing";
}

std::string formatNumber(double value) {
    std::ostringstream out;
    out.precision(10);
    out << value;
    return out.str();
}

bool isBareKey(std::string_view key) {
    return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == '-';
    });
}

void wrongType(const toml::node& node, const std::string& key, std::string_view expected,
               ProblemSink& sink) {
    sink.add(node.source(), key,
             "expected " + std::string(expected) + ", got " + typeName(node.type()));
}

} // namespace

void ProblemSink::add(const toml::source_region& where, std::string key, std::string message) {
    if (problems_.size() >= kMaxProblems) {
        ++dropped_;
        return;
    }
    problems_.push_back({file_, static_cast<int>(where.begin.line),
                         static_cast<int>(where.begin.column), std::move(key), std::move(message)});
}

std::vector<ConfigProblem> ProblemSink::take() {
    if (dropped_ > 0) {
        problems_.push_back(
            {file_, 0, 0, "", std::to_string(dropped_) + " more problems not listed"});
        dropped_ = 0;
    }
    return std::move(problems_);
}

std::string keyPath(std::string_view prefix, std::string_view key) {
    std::string out(prefix);
    if (!out.empty()) {
        out += '.';
    }
    if (isBareKey(key)) {
        out += key;
    } else {
        out += '"';
        out += key;
        out += '"';
    }
    return out;
}

std::optional<double> readNumber(const toml::node& node, const std::string& key,
                                 const NumberRange& range, ProblemSink& sink) {
    double value = 0.0;
    if (const auto* integer = node.as_integer()) {
        value = static_cast<double>(integer->get());
    } else if (const auto* floating = node.as_floating_point()) {
        value = floating->get();
    } else {
        wrongType(node, key, "a number", sink);
        return std::nullopt;
    }
    // Written so that nan and inf (valid TOML) fail too.
    const bool aboveMin = range.minExclusive ? value > range.min : value >= range.min;
    if (!(aboveMin && value <= range.max)) {
        sink.add(node.source(), key,
                 "is " + formatNumber(value) + "; must be " +
                     (range.minExclusive ? "above " : "at least ") + formatNumber(range.min) +
                     " and at most " + formatNumber(range.max));
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> readText(const toml::node& node, const std::string& key,
                                    const TextCheck& check, ProblemSink& sink) {
    const auto* text = node.as_string();
    if (text == nullptr) {
        wrongType(node, key, "a string", sink);
        return std::nullopt;
    }
    const std::string& value = text->get();
    if (value.size() > kMaxTextBytes) {
        sink.add(node.source(), key,
                 "is " + std::to_string(value.size()) + " bytes long; at most " +
                     std::to_string(kMaxTextBytes));
        return std::nullopt;
    }
    if (check) {
        if (std::string why = check(value); !why.empty()) {
            sink.add(node.source(), key, std::move(why));
            return std::nullopt;
        }
    }
    return value;
}

const toml::node* TableReader::ask(std::string_view key) {
    known_.emplace_back(key);
    return table_.get(key);
}

std::optional<long long> TableReader::integer(std::string_view key, const IntRange& range) {
    const toml::node* node = ask(key);
    if (node == nullptr) {
        return std::nullopt;
    }
    const auto* integer = node->as_integer();
    if (integer == nullptr) {
        wrongType(*node, path(key), "an integer", sink_);
        return std::nullopt;
    }
    const long long value = integer->get();
    if (value < range.min || value > range.max) {
        sink_.add(node->source(), path(key),
                  "is " + std::to_string(value) + "; must be at least " +
                      std::to_string(range.min) + " and at most " + std::to_string(range.max));
        return std::nullopt;
    }
    return value;
}

std::optional<double> TableReader::number(std::string_view key, const NumberRange& range) {
    const toml::node* node = ask(key);
    return node == nullptr ? std::nullopt : readNumber(*node, path(key), range, sink_);
}

std::optional<bool> TableReader::boolean(std::string_view key) {
    const toml::node* node = ask(key);
    if (node == nullptr) {
        return std::nullopt;
    }
    if (const auto* value = node->as_boolean()) {
        return value->get();
    }
    wrongType(*node, path(key), "true or false", sink_);
    return std::nullopt;
}

std::optional<std::string> TableReader::text(std::string_view key, const TextCheck& check) {
    const toml::node* node = ask(key);
    return node == nullptr ? std::nullopt : readText(*node, path(key), check, sink_);
}

const toml::table* TableReader::table(std::string_view key) {
    const toml::node* node = ask(key);
    if (node == nullptr) {
        return nullptr;
    }
    if (const auto* table = node->as_table()) {
        return table;
    }
    wrongType(*node, path(key), "a table", sink_);
    return nullptr;
}

const toml::array* TableReader::array(std::string_view key) {
    const toml::node* node = ask(key);
    if (node == nullptr) {
        return nullptr;
    }
    if (const auto* array = node->as_array()) {
        return array;
    }
    wrongType(*node, path(key), "an array", sink_);
    return nullptr;
}

void TableReader::problem(std::string_view key, std::string message) {
    const toml::node* node = table_.get(key);
    sink_.add(node != nullptr ? node->source() : table_.source(), path(key), std::move(message));
}

void TableReader::reportUnknownKeys() {
    std::string known;
    for (const std::string& name : known_) {
        known += (known.empty() ? "" : ", ") + name;
    }
    for (auto&& [key, node] : table_) {
        if (std::find(known_.begin(), known_.end(), key.str()) == known_.end()) {
            sink_.add(key.source(), path(key.str()),
                      known.empty() ? "unknown key" : "unknown key; known here: " + known);
        }
    }
}

} // namespace steerseg::config::detail
