#include "platform/kms/output_selection.hpp"

#include <charconv>

namespace steerseg::platform::kms {

namespace {

// A positive decimal number filling [first, last) exactly.
bool parsePositive(const char* first, const char* last, int& value) {
    if (first == last) {
        return false;
    }
    const auto [end, error] = std::from_chars(first, last, value);
    return error == std::errc() && end == last && value > 0;
}

std::string joinNames(const std::vector<ConnectorInfo>& connectors) {
    std::string names;
    for (const ConnectorInfo& c : connectors) {
        names += (names.empty() ? "" : ", ") + c.name + (c.connected ? "" : " (disconnected)");
    }
    return names.empty() ? "none" : names;
}

std::string describe(const ModeRequest& r) {
    std::string text = std::to_string(r.width) + "x" + std::to_string(r.height);
    if (r.refreshHz > 0) {
        text += "@" + std::to_string(r.refreshHz);
    }
    return text;
}

std::string joinModes(const std::vector<ModeInfo>& modes) {
    std::string text;
    for (const ModeInfo& m : modes) {
        text += (text.empty() ? "" : ", ") + std::to_string(m.width) + "x" +
                std::to_string(m.height) + "@" + std::to_string(m.refreshHz);
    }
    return text.empty() ? "none" : text;
}

std::size_t chooseMode(const ConnectorInfo& connector, const std::string& requested) {
    const std::vector<ModeInfo>& modes = connector.modes;
    if (modes.empty()) {
        throw DisplayError("kms: connector " + connector.name + " lists no modes");
    }
    if (!requested.empty()) {
        const ModeRequest want = parseModeRequest(requested);
        std::optional<std::size_t> best;
        for (std::size_t i = 0; i < modes.size(); ++i) {
            const ModeInfo& m = modes[i];
            if (m.width != want.width || m.height != want.height ||
                (want.refreshHz > 0 && m.refreshHz != want.refreshHz)) {
                continue;
            }
            if (!best || m.refreshHz > modes[*best].refreshHz) {
                best = i;
            }
        }
        if (!best) {
            throw DisplayError("kms: no mode " + describe(want) + " on " + connector.name +
                               " (modes: " + joinModes(modes) + ")");
        }
        return *best;
    }
    for (std::size_t i = 0; i < modes.size(); ++i) {
        if (modes[i].preferred) {
            return i;
        }
    }
    std::size_t largest = 0;
    for (std::size_t i = 1; i < modes.size(); ++i) {
        const long long area = static_cast<long long>(modes[i].width) * modes[i].height;
        const long long best = static_cast<long long>(modes[largest].width) * modes[largest].height;
        if (area > best || (area == best && modes[i].refreshHz > modes[largest].refreshHz)) {
            largest = i;
        }
    }
    return largest;
}

} // namespace

ModeRequest parseModeRequest(const std::string& text) {
    const auto bad = [&text]() {
        return DisplayError("kms: bad mode \"" + text + "\" (expected WxH or WxH@HZ)");
    };
    const std::size_t x = text.find('x');
    if (x == std::string::npos) {
        throw bad();
    }
    const std::size_t at = text.find('@', x);
    const std::size_t heightEnd = at == std::string::npos ? text.size() : at;
    ModeRequest request;
    const char* begin = text.data();
    if (!parsePositive(begin, begin + x, request.width) ||
        !parsePositive(begin + x + 1, begin + heightEnd, request.height) ||
        (at != std::string::npos &&
         !parsePositive(begin + at + 1, begin + text.size(), request.refreshHz))) {
        throw bad();
    }
    return request;
}

OutputChoice selectOutput(const std::vector<ConnectorInfo>& connectors,
                          const DisplayOptions& options) {
    OutputChoice choice;
    if (!options.connector.empty()) {
        std::optional<std::size_t> found;
        for (std::size_t i = 0; i < connectors.size(); ++i) {
            if (connectors[i].name == options.connector) {
                found = i;
            }
        }
        if (!found) {
            throw DisplayError("kms: no connector named " + options.connector +
                               " (found: " + joinNames(connectors) + ")");
        }
        if (!connectors[*found].connected) {
            throw DisplayError("kms: connector " + options.connector + " is not connected");
        }
        choice.connector = *found;
    } else {
        std::optional<std::size_t> found;
        for (std::size_t i = 0; i < connectors.size() && !found; ++i) {
            if (connectors[i].connected) {
                found = i;
            }
        }
        if (!found) {
            throw DisplayError("kms: no connected connector (found: " + joinNames(connectors) +
                               ")");
        }
        choice.connector = *found;
    }
    choice.mode = chooseMode(connectors[choice.connector], options.mode);
    return choice;
}

std::optional<double> dpiOf(const ModeInfo& mode, int mmWidth) {
    // Below 5 cm no real panel; EDIDs of projectors and some adapters put 0 or 1 cm here.
    if (mmWidth < 50 || mode.width <= 0) {
        return std::nullopt;
    }
    return static_cast<double>(mode.width) * 25.4 / static_cast<double>(mmWidth);
}

} // namespace steerseg::platform::kms
