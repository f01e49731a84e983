#include "platform/input/hid/report_descriptor.hpp"

#include <array>

namespace steerseg::platform::input::hid {

namespace {

// Limits far above any real controller's, low enough that a hostile descriptor stays cheap.
constexpr std::uint32_t kMaxReportSizeBits = 256;
constexpr std::uint32_t kMaxReportCount = 4096;
constexpr std::size_t kMaxInputFields = 8192;
constexpr std::uint32_t kMaxReportBits = 8 * 4096;
constexpr std::size_t kMaxPushDepth = 16;
constexpr std::size_t kMaxCollectionDepth = 32;
constexpr std::size_t kMaxCollections = 1024;
constexpr std::size_t kMaxLocalUsages = 1024;

struct GlobalState {
    std::uint16_t usagePage = 0;
    std::int64_t logicalMin = 0;
    std::uint32_t logicalMaxRaw = 0;
    std::uint8_t logicalMaxBytes = 0;
    std::uint32_t reportSize = 0;
    std::uint32_t reportCount = 0;
    std::uint8_t reportId = 0;
};

// A usage or a usage range, the page resolved when the local item was read.
struct UsageRange {
    std::uint16_t page = 0;
    std::uint32_t first = 0;
    std::uint32_t count = 1;
};

struct LocalState {
    std::vector<UsageRange> usages;
    std::optional<std::uint32_t> rangeMin; // a Usage Minimum waiting for its maximum
    std::uint16_t rangePage = 0;
};

// The i-th usage of the local list; the last one repeats (HID 1.11, section 6.2.2.8).
std::pair<std::uint16_t, std::uint16_t> usageAt(const std::vector<UsageRange>& usages,
                                                std::uint32_t index) {
    if (usages.empty()) {
        return {0, 0};
    }
    for (const UsageRange& r : usages) {
        if (index < r.count) {
            return {r.page, static_cast<std::uint16_t>(r.first + index)};
        }
        index -= r.count;
    }
    const UsageRange& last = usages.back();
    return {last.page, static_cast<std::uint16_t>(last.first + last.count - 1)};
}

std::int64_t signedData(std::uint32_t data, std::size_t size) {
    switch (size) {
    case 1:
        return static_cast<std::int8_t>(data);
    case 2:
        return static_cast<std::int16_t>(data);
    case 4:
        return static_cast<std::int32_t>(data);
    default:
        return 0;
    }
}

// Splits a 4-byte usage into page and id; a shorter one takes the current page.
UsageRange usageFrom(std::uint32_t data, std::size_t size, std::uint16_t page) {
    if (size == 4) {
        return {static_cast<std::uint16_t>(data >> 16), data & 0xFFFFU, 1};
    }
    return {page, data & 0xFFFFU, 1};
}

class Parser {
  public:
    std::optional<ReportDescriptor> run(std::span<const std::uint8_t> bytes, std::string& problem);

  private:
    bool fail(std::string line) {
        problem_ = "report descriptor at byte " + std::to_string(at_) + ": " + std::move(line);
        return false;
    }
    bool mainItem(unsigned tag, std::uint32_t data);
    bool globalItem(unsigned tag, std::uint32_t data, std::size_t size);
    bool localItem(unsigned tag, std::uint32_t data, std::size_t size);
    bool addInputs(std::uint32_t flags);

    ReportDescriptor out_;
    GlobalState global_;
    std::vector<GlobalState> pushed_;
    LocalState local_;
    std::vector<int> open_; // indices of the open collections, innermost last
    std::size_t at_ = 0;
    bool sawReportId_ = false;
    bool sawInputBeforeId_ = false;
    std::string problem_;
};

std::optional<ReportDescriptor> Parser::run(std::span<const std::uint8_t> bytes,
                                            std::string& problem) {
    if (bytes.size() > kMaxDescriptorBytes) {
        problem = "report descriptor of " + std::to_string(bytes.size()) + " bytes, over the " +
                  std::to_string(kMaxDescriptorBytes) + "-byte limit";
        return std::nullopt;
    }
    if (bytes.empty()) {
        problem = "report descriptor is empty";
        return std::nullopt;
    }
    while (at_ < bytes.size()) {
        const std::uint8_t prefix = bytes[at_];
        if (prefix == 0xFE) { // a long item: no standard tag uses it, skip its data
            if (at_ + 3 > bytes.size() || at_ + 3 + bytes[at_ + 1] > bytes.size()) {
                fail("long item runs past the end");
                problem = problem_;
                return std::nullopt;
            }
            at_ += 3 + std::size_t{bytes[at_ + 1]};
            continue;
        }
        static constexpr std::array<std::size_t, 4> kSizes{0, 1, 2, 4};
        const std::size_t size = kSizes[prefix & 3U];
        if (at_ + 1 + size > bytes.size()) {
            fail("item runs past the end");
            problem = problem_;
            return std::nullopt;
        }
        std::uint32_t data = 0;
        for (std::size_t i = 0; i < size; ++i) {
            data |= std::uint32_t{bytes[at_ + 1 + i]} << (8 * i);
        }
        const unsigned type = (prefix >> 2) & 3U;
        const unsigned tag = prefix >> 4;
        bool ok = true;
        switch (type) {
        case 0:
            ok = mainItem(tag, data);
            break;
        case 1:
            ok = globalItem(tag, data, size);
            break;
        case 2:
            ok = localItem(tag, data, size);
            break;
        default:
            ok = fail("reserved item type");
            break;
        }
        if (!ok) {
            problem = problem_;
            return std::nullopt;
        }
        at_ += 1 + size;
    }
    if (sawReportId_ && sawInputBeforeId_) {
        problem = "report descriptor: input fields both with and without a report id";
        return std::nullopt;
    }
    out_.usesReportIds = sawReportId_;
    return std::move(out_);
}

bool Parser::mainItem(unsigned tag, std::uint32_t data) {
    switch (tag) {
    case 0x8: // Input
        if (!addInputs(data)) {
            return false;
        }
        break;
    case 0x9: // Output
    case 0xB: // Feature
        break;
    case 0xA: { // Collection
        if (open_.size() >= kMaxCollectionDepth) {
            return fail("collections nested over " + std::to_string(kMaxCollectionDepth) + " deep");
        }
        if (out_.collections.size() >= kMaxCollections) {
            return fail("over " + std::to_string(kMaxCollections) + " collections");
        }
        const auto [page, usage] = usageAt(local_.usages, 0);
        out_.collections.push_back(
            {page, usage, static_cast<std::uint8_t>(data), open_.empty() ? -1 : open_.back()});
        open_.push_back(static_cast<int>(out_.collections.size() - 1));
        break;
    }
    case 0xC: // End Collection
        if (open_.empty()) {
            return fail("End Collection without a Collection");
        }
        open_.pop_back();
        break;
    default:
        return fail("unknown main item tag " + std::to_string(tag));
    }
    local_ = LocalState{}; // local items apply to the next main item only
    return true;
}

bool Parser::addInputs(std::uint32_t flags) {
    const GlobalState& g = global_;
    if (g.reportSize == 0 || g.reportCount == 0) {
        return true; // occupies no bits
    }
    if (g.reportId == 0) {
        sawInputBeforeId_ = true;
    }
    std::uint32_t& bits = out_.inputBits[g.reportId];
    const std::uint64_t end = std::uint64_t{bits} + std::uint64_t{g.reportSize} * g.reportCount;
    if (end > kMaxReportBits) {
        return fail("input report " + std::to_string(g.reportId) + " over " +
                    std::to_string(kMaxReportBits / 8) + " bytes");
    }
    if (out_.inputs.size() + g.reportCount > kMaxInputFields) {
        return fail("over " + std::to_string(kMaxInputFields) + " input fields");
    }
    HidField field;
    field.reportId = g.reportId;
    field.bitSize = g.reportSize;
    field.logicalMin = g.logicalMin;
    field.logicalMax = g.logicalMin < 0 ? signedData(g.logicalMaxRaw, g.logicalMaxBytes)
                                        : std::int64_t{g.logicalMaxRaw};
    field.isSigned = g.logicalMin < 0;
    field.constant = (flags & 1U) != 0;
    field.variable = (flags & 2U) != 0;
    field.relative = (flags & 4U) != 0;
    field.collection = open_.empty() ? -1 : open_.back();
    for (std::uint32_t i = 0; i < g.reportCount; ++i) {
        const auto [page, usage] = usageAt(local_.usages, field.variable ? i : 0);
        field.usagePage = page;
        field.usage = usage;
        field.bitOffset = bits + i * g.reportSize;
        out_.inputs.push_back(field);
    }
    bits = static_cast<std::uint32_t>(end);
    return true;
}

bool Parser::globalItem(unsigned tag, std::uint32_t data, std::size_t size) {
    switch (tag) {
    case 0x0:
        global_.usagePage = static_cast<std::uint16_t>(data);
        break;
    case 0x1:
        global_.logicalMin = signedData(data, size);
        break;
    case 0x2:
        global_.logicalMaxRaw = data;
        global_.logicalMaxBytes = static_cast<std::uint8_t>(size);
        break;
    case 0x7:
        if (data > kMaxReportSizeBits) {
            return fail("report size of " + std::to_string(data) + " bits, over " +
                        std::to_string(kMaxReportSizeBits));
        }
        global_.reportSize = data;
        break;
    case 0x8:
        if (data == 0 || data > 255) {
            return fail("report id " + std::to_string(data) + " outside 1..255");
        }
        global_.reportId = static_cast<std::uint8_t>(data);
        sawReportId_ = true;
        break;
    case 0x9:
        if (data > kMaxReportCount) {
            return fail("report count of " + std::to_string(data) + ", over " +
                        std::to_string(kMaxReportCount));
        }
        global_.reportCount = data;
        break;
    case 0xA: // Push
        if (pushed_.size() >= kMaxPushDepth) {
            return fail("Push nested over " + std::to_string(kMaxPushDepth) + " deep");
        }
        pushed_.push_back(global_);
        break;
    case 0xB: // Pop
        if (pushed_.empty()) {
            return fail("Pop without a Push");
        }
        global_ = pushed_.back();
        pushed_.pop_back();
        break;
    default: // physical range, unit, unit exponent: not needed to read a field
        break;
    }
    return true;
}

bool Parser::localItem(unsigned tag, std::uint32_t data, std::size_t size) {
    if (local_.usages.size() >= kMaxLocalUsages) {
        return fail("over " + std::to_string(kMaxLocalUsages) + " usages before one main item");
    }
    switch (tag) {
    case 0x0: // Usage
        local_.usages.push_back(usageFrom(data, size, global_.usagePage));
        break;
    case 0x1: { // Usage Minimum
        const UsageRange u = usageFrom(data, size, global_.usagePage);
        local_.rangeMin = u.first;
        local_.rangePage = u.page;
        break;
    }
    case 0x2: { // Usage Maximum
        const UsageRange u = usageFrom(data, size, global_.usagePage);
        if (local_.rangeMin && u.first >= *local_.rangeMin) {
            local_.usages.push_back(
                {local_.rangePage, *local_.rangeMin, u.first - *local_.rangeMin + 1});
        }
        local_.rangeMin.reset();
        break;
    }
    default: // designators, strings, delimiters: not needed to read a field
        break;
    }
    return true;
}

} // namespace

std::size_t ReportDescriptor::inputReportBytes(std::uint8_t reportId) const {
    const std::uint32_t bits = inputBits[reportId];
    if (bits == 0 || (usesReportIds && reportId == 0)) {
        return 0;
    }
    return (bits + 7) / 8 + (usesReportIds ? 1 : 0);
}

bool ReportDescriptor::within(const HidField& field, int ancestor) const {
    // Parents always precede their children, so the walk ends within collections.size() steps.
    for (int c = field.collection; c >= 0; c = collections[static_cast<std::size_t>(c)].parent) {
        if (c == ancestor) {
            return true;
        }
    }
    return false;
}

std::optional<ReportDescriptor> parseReportDescriptor(std::span<const std::uint8_t> bytes,
                                                      std::string& problem) {
    return Parser().run(bytes, problem);
}

} // namespace steerseg::platform::input::hid
