#include "cli/args.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace steerseg::cli {

Args::Args(std::span<const std::string> words, const std::vector<std::string>& valueOptions,
           const std::vector<std::string>& flagOptions) {
    auto contains = [](const std::vector<std::string>& v, const std::string& s) {
        return std::find(v.begin(), v.end(), s) != v.end();
    };
    for (std::size_t n = 0; n < words.size(); ++n) {
        const std::string& w = words[n];
        if (w.rfind("--", 0) != 0 || w.size() == 2) {
            positional_.push_back(w);
            continue;
        }
        std::string name = w.substr(2);
        std::optional<std::string> inlineValue;
        if (auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (contains(flagOptions, name)) {
            if (inlineValue) {
                throw UsageError("--" + name + " takes no value");
            }
            flags_.push_back(name);
        } else if (contains(valueOptions, name)) {
            if (inlineValue) {
                values_[name].push_back(*inlineValue);
            } else if (n + 1 < words.size()) {
                values_[name].push_back(words[++n]);
            } else {
                throw UsageError("--" + name + " needs a value");
            }
        } else {
            throw UsageError("unknown option --" + name);
        }
    }
}

bool Args::flag(const std::string& name) const {
    return std::find(flags_.begin(), flags_.end(), name) != flags_.end();
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) {
        return std::nullopt;
    }
    if (it->second.size() > 1) {
        throw UsageError("--" + name + " given more than once");
    }
    return it->second.front();
}

std::string Args::required(const std::string& name) const {
    auto v = value(name);
    if (!v) {
        throw UsageError("--" + name + " is required");
    }
    return *v;
}

std::vector<std::string> Args::values(const std::string& name) const {
    auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::optional<double> Args::number(const std::string& name) const {
    auto v = value(name);
    if (!v) {
        return std::nullopt;
    }
    return parseNumber(*v, "--" + name);
}

std::optional<long long> Args::integer(const std::string& name) const {
    auto v = value(name);
    if (!v) {
        return std::nullopt;
    }
    return parseInteger(*v, "--" + name);
}

double parseNumber(const std::string& text, const std::string& what) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
        throw UsageError(what + ": expected a finite number, got '" + text + "'");
    }
    return v;
}

long long parseInteger(const std::string& text, const std::string& what) {
    long long v = 0;
    const auto* first = text.data();
    const auto* last = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(first, last, v);
    if (text.empty() || ec != std::errc{} || ptr != last) {
        throw UsageError(what + ": expected an integer, got '" + text + "'");
    }
    return v;
}

std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what) {
    std::vector<double> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        out.push_back(parseNumber(text.substr(start, comma - start), what));
        if (comma == std::string::npos) {
            break;
        }
        start = comma + 1;
    }
    if (out.size() != count) {
        throw UsageError(what + ": expected " + std::to_string(count) +
                         " comma-separated numbers, got '" + text + "'");
    }
    return out;
}

std::pair<int, int> parseSize(const std::string& text, const std::string& what, int minSide,
                              int maxSide) {
    const auto x = text.find('x');
    if (x == std::string::npos) {
        throw UsageError(what + ": expected WIDTHxHEIGHT, got '" + text + "'");
    }
    const long long w = parseInteger(text.substr(0, x), what + " width");
    const long long h = parseInteger(text.substr(x + 1), what + " height");
    if (w < minSide || h < minSide || w > maxSide || h > maxSide) {
        throw UsageError(what + ": width and height must be " + std::to_string(minSide) + ".." +
                         std::to_string(maxSide) + ", got '" + text + "'");
    }
    return {static_cast<int>(w), static_cast<int>(h)};
}

} // namespace steerseg::cli
