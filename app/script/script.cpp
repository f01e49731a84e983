// The script parser: each line's timing, its verb looked up in the verb tables
// (script_verbs*.cpp), and the checks every line and file gets.
#include "script/script.hpp"

#include "script/script_tokens.hpp"
#include "script/script_verbs.hpp"
#include "script/script_words.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

namespace steerseg::script {

namespace {

using detail::kMaxSeconds;
using detail::LineError;
using detail::Words;
constexpr int kMaxErrors = 50;
constexpr int kMaxControlLines = 3; // more lines with control characters: a binary file

const detail::VerbTable& verbs() {
    static const detail::VerbTable kVerbs = [] {
        detail::VerbTable table;
        detail::addDeviceVerbs(table);
        detail::addOperatorVerbs(table);
        detail::addPacsVerbs(table);
        detail::addCheckVerbs(table);
        return table;
    }();
    return kVerbs;
}

std::string trimmed(std::string_view line) {
    const std::size_t begin = line.find_first_not_of(" \t");
    if (begin == std::string_view::npos) {
        return {};
    }
    const std::size_t end = line.find_last_not_of(" \t");
    return std::string(line.substr(begin, end - begin + 1));
}

// Parses one line; nullopt for a blank or comment line.
std::optional<Step> parseLine(std::string_view line, int number, double& lastAt) {
    std::vector<std::string> words = detail::splitWords(line);
    if (words.empty()) {
        return std::nullopt;
    }
    Step step;
    step.line = number;
    step.text = trimmed(detail::withoutComment(line));
    std::size_t first = 0;
    if (words[0] == "at" || words[0] == "after") {
        Words timing(words, 1);
        const double seconds = timing.number(
            words[0] == "at" ? "the time after 'at'" : "the delay after 'after'", 0.0, kMaxSeconds);
        step.timing = {words[0] == "at" ? Timing::At : Timing::After, seconds};
        if (step.timing.kind == Timing::At) {
            if (seconds < lastAt) {
                char text[128];
                std::snprintf(text, sizeof text,
                              "at %g goes back in time (an earlier step is at %g)", seconds,
                              lastAt);
                throw LineError(text);
            }
            lastAt = seconds;
        }
        first = 2;
        if (words.size() <= first) {
            throw LineError("'" + words[0] + " " + words[1] + "' names no step after the time");
        }
    }
    const auto& table = verbs();
    const auto it = table.find(words[first]);
    if (it == table.end()) {
        std::string verb = words[first].substr(0, 40);
        throw LineError("unknown step '" + verb + "' (docs/scripts.md lists the steps)");
    }
    Words rest(std::move(words), first + 1);
    step.kind = it->second(rest);
    return step;
}

// A control character other than a tab, or a carriage return ending a line.
bool isControl(char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && c != '\t' && c != '\n' && c != '\r') || u == 0x7F;
}

// Lines of `text` holding a control character, and where the first one is: a stray character in
// a text file is one line's problem, a file full of them is not a script at all.
struct ControlLines {
    int lines = 0;
    int firstLine = 0;
    char first = 0;
};

ControlLines controlLines(std::string_view text) {
    ControlLines found;
    int line = 1;
    bool counted = false;
    for (const char c : text) {
        if (c == '\n') {
            ++line;
            counted = false;
        } else if (isControl(c) && !counted) {
            counted = true;
            if (found.lines++ == 0) {
                found.firstLine = line;
                found.first = c;
            }
        }
    }
    return found;
}

// Raw lines pasted from a recording keep their spacing: a timed raw line without its own `at` or
// `after` comes that long after the timed raw line before it (the first of a run at once).
// A replay's relative path is the script's folder's, like the lines it stands for.
void spaceRawLines(Step& step, double& lastRaw, const std::string& scriptName) {
    auto* raw = std::get_if<RawStep>(&step.kind);
    if (raw == nullptr) {
        lastRaw = -1.0;
        return;
    }
    if (!raw->record) {
        lastRaw = -1.0;
        const std::filesystem::path path(raw->recording);
        if (path.is_relative() && !raw->recording.starts_with('$')) {
            raw->recording = (std::filesystem::path(scriptName).parent_path() / path).string();
        }
        return;
    }
    const double time = raw->record->time;
    if (time < 0.0) {
        lastRaw = -1.0;
        return;
    }
    if (step.timing.kind == Timing::Next && lastRaw >= 0.0 && time >= lastRaw) {
        step.timing = {Timing::After, time - lastRaw};
    }
    lastRaw = time;
}

} // namespace

Script parseScript(std::string_view text, const std::string& name) {
    if (text.size() > kMaxScriptBytes) {
        throw ScriptError(name + ": the script is " + std::to_string(text.size()) +
                          " bytes; at most " + std::to_string(kMaxScriptBytes));
    }
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        throw ScriptError(name + ": not a text file (a NUL byte at offset " + std::to_string(nul) +
                          ")");
    }
    if (const ControlLines control = controlLines(text); control.lines > kMaxControlLines) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02X",
                      static_cast<unsigned>(static_cast<unsigned char>(control.first)));
        throw ScriptError(name + ": not a text file (control characters on " +
                          std::to_string(control.lines) + " lines, the first " + code +
                          " on line " + std::to_string(control.firstLine) + ")");
    }
    Script script;
    script.name = name;
    std::vector<std::string> errors;
    double lastAt = 0.0;
    double lastRaw = -1.0; // the time of the raw line just before, < 0 when there was none
    int number = 0;
    std::size_t pos = 0;
    while (pos < text.size() && static_cast<int>(errors.size()) < kMaxErrors) {
        ++number;
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) {
            end = text.size();
        }
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (line.ends_with('\r')) {
            line.remove_suffix(1);
        }
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (line.size() > kMaxLineLength) {
            errors.push_back(where + "the line is " + std::to_string(line.size()) +
                             " characters long; at most " + std::to_string(kMaxLineLength));
            continue;
        }
        const auto control = std::find_if(line.begin(), line.end(), [](char c) {
            const auto u = static_cast<unsigned char>(c);
            return (u < 0x20 && c != '\t') || u == 0x7F;
        });
        if (control != line.end()) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02X",
                          static_cast<unsigned>(static_cast<unsigned char>(*control)));
            errors.push_back(where + "a control character (" + code +
                             ") in the line; is this a text file?");
            continue;
        }
        try {
            if (auto step = parseLine(line, number, lastAt)) {
                spaceRawLines(*step, lastRaw, name);
                script.steps.push_back(std::move(*step));
            }
        } catch (const LineError& e) {
            errors.push_back(where + e.what());
        }
    }
    if (static_cast<int>(errors.size()) >= kMaxErrors && pos < text.size()) {
        errors.push_back(name + ": more errors after line " + std::to_string(number) +
                         " not listed");
    }
    if (!errors.empty()) {
        std::string all;
        for (const std::string& e : errors) {
            all += (all.empty() ? "" : "\n") + e;
        }
        throw ScriptError(all);
    }
    if (script.steps.empty()) {
        throw ScriptError(name + ": the script has no steps");
    }
    return script;
}

Script loadScript(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec || !std::filesystem::exists(status)) {
        throw ScriptError(name + ": no such script file");
    }
    if (std::filesystem::is_directory(status)) {
        throw ScriptError(name + ": is a folder, not a script file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw ScriptError(name + ": cannot open the script (" + std::strerror(errno) + ")");
    }
    std::string text;
    text.resize(kMaxScriptBytes + 1);
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) {
        throw ScriptError(name + ": cannot read the script");
    }
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxScriptBytes) {
        throw ScriptError(name + ": the script is larger than " + std::to_string(kMaxScriptBytes) +
                          " bytes");
    }
    return parseScript(text, name);
}

const std::vector<std::string_view>& scriptVariables() {
    static const std::vector<std::string_view> kNames = {"SCAN",     "DATA",  "OUT",   "EXPORTED",
                                                         "RECEIVED", "FOUND", "SERIES"};
    return kNames;
}

} // namespace steerseg::script
