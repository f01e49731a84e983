#include "scan/dicom/structure.hpp"

#include "scan/byte_source.hpp"

#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace steerseg::scan {

namespace {

// Deflated data sets (rare: mostly structured reports) are inflated in memory to be checked.
constexpr std::size_t kMaxInflatedBytes = std::size_t{256} << 20;
constexpr std::uint32_t kUndefined = 0xffffffffU;
constexpr std::uint32_t kItem = 0xfffee000U;
constexpr std::uint32_t kItemEnd = 0xfffee00dU;
constexpr std::uint32_t kSequenceEnd = 0xfffee0ddU;
constexpr std::uint32_t kPixelData = 0x7fe00010U;

enum class Syntax { ExplicitLittle, ImplicitLittle, ExplicitBig };

bool validVr(const std::array<char, 2>& vr) {
    static constexpr const char* kAll[] = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL",
                                           "IS", "LO", "LT", "OB", "OD", "OF", "OL", "OV", "OW",
                                           "PN", "SH", "SL", "SQ", "SS", "ST", "SV", "TM", "UC",
                                           "UI", "UL", "UN", "UR", "US", "UT", "UV"};
    for (const char* v : kAll) {
        if (vr[0] == v[0] && vr[1] == v[1]) {
            return true;
        }
    }
    return false;
}

// VRs whose explicit length field is 4 bytes after 2 reserved ones.
bool longVr(const std::array<char, 2>& vr) {
    static constexpr const char* kLong[] = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                            "SV", "UC", "UN", "UR", "UT", "UV"};
    for (const char* v : kLong) {
        if (vr[0] == v[0] && vr[1] == v[1]) {
            return true;
        }
    }
    return false;
}

class Walker {
  public:
    Walker(const std::filesystem::path& path, std::istream& in, std::uint64_t size)
        : path_(path), in_(in), size_(size) {}

    std::uint64_t pos = 0;
    std::uint64_t paddingStart = 0; // where trailing zero padding starts, if any

    void read(void* dst, std::uint64_t n, std::uint64_t end) {
        if (n > end - pos) {
            fail("ends inside an element header");
        }
        in_.seekg(static_cast<std::streamoff>(pos));
        if (!in_.read(static_cast<char*>(dst), static_cast<std::streamsize>(n))) {
            fail("cannot be read");
        }
        pos += n;
    }
    std::uint16_t u16(std::uint64_t end, bool big) {
        std::array<unsigned char, 2> b{};
        read(b.data(), 2, end);
        return big ? static_cast<std::uint16_t>(b[0] << 8 | b[1])
                   : static_cast<std::uint16_t>(b[1] << 8 | b[0]);
    }
    std::uint32_t u32(std::uint64_t end, bool big) {
        std::array<unsigned char, 4> b{};
        read(b.data(), 4, end);
        const auto w = [&](int i) {
            return static_cast<std::uint32_t>(b[static_cast<std::size_t>(i)]);
        };
        return big ? (w(0) << 24 | w(1) << 16 | w(2) << 8 | w(3))
                   : (w(3) << 24 | w(2) << 16 | w(1) << 8 | w(0));
    }
    std::uint32_t tag(std::uint64_t end, bool big) {
        const std::uint32_t group = u16(end, big);
        return group << 16 | u16(end, big);
    }

    [[noreturn]] void fail(const std::string& problem) const {
        char where[64];
        std::snprintf(where, sizeof where, "at byte %llu", static_cast<unsigned long long>(pos));
        throw ScanError(path_, "not a well-formed DICOM file: " + problem + " (" + where + ")");
    }
    [[noreturn]] void failTag(std::uint32_t t, const std::string& problem) const {
        char text[32];
        std::snprintf(text, sizeof text, "element (%04x,%04x) ", t >> 16, t & 0xffffU);
        fail(text + problem);
    }

    // Elements from pos up to `end` (or up to `stop` when the container has undefined length).
    // Returns when the delimiter `stop` (item or sequence end) is consumed.
    void elements(std::uint64_t end, Syntax syntax, int depth, std::uint32_t stop, bool topLevel) {
        const bool big = syntax == Syntax::ExplicitBig;
        std::uint32_t previous = 0;
        bool first = true;
        while (pos < end) {
            if (topLevel && allZeroFrom(pos, end)) {
                paddingStart = pos; // trailing zero padding
                return;
            }
            const std::uint32_t t = tag(end, big);
            if (stop != 0 && t == stop) {
                if (u32(end, big) != 0) {
                    failTag(t, "(a delimiter) has a non-zero length");
                }
                return;
            }
            if (t == kItem || t == kItemEnd || t == kSequenceEnd) {
                failTag(t, "(an item tag) appears outside a sequence");
            }
            // GDCM falls back to guessing (and asserts) on unordered or command-group tags.
            if ((!first && t <= previous) || (t >> 16) <= 0x0002) {
                failTag(t, "is out of order or in a group that does not belong in a data set");
            }
            previous = t;
            first = false;
            std::uint32_t length = 0;
            bool maySequence = false;
            Syntax inner = syntax;
            if (syntax == Syntax::ImplicitLittle) {
                length = u32(end, big);
                maySequence = t != kPixelData;
            } else {
                std::array<char, 2> vr{};
                read(vr.data(), 2, end);
                if (!validVr(vr)) {
                    failTag(t, "has no valid VR");
                }
                const std::string v(vr.data(), 2);
                if (longVr(vr)) {
                    (void)u16(end, big);
                    length = u32(end, big);
                } else {
                    length = u16(end, big);
                }
                if (t == kPixelData && v != "OB" && v != "OW") {
                    failTag(t, "(pixel data) has VR " + v + ", not OB or OW");
                }
                maySequence = v == "SQ" || v == "UN";
                if (v == "UN") {
                    inner = Syntax::ImplicitLittle; // an undefined-length UN holds implicit VR
                }
                if (length == kUndefined && !(maySequence || (t == kPixelData && v[0] == 'O'))) {
                    failTag(t, "has undefined length but is not a sequence");
                }
            }
            if (length == kUndefined) {
                if (depth >= kMaxDicomNesting) {
                    failTag(t, "nests sequences too deeply");
                }
                if (t == kPixelData) {
                    fragments(end);
                } else {
                    items(end, inner, depth + 1);
                }
                continue;
            }
            if (length > end - pos) {
                failTag(t, "claims " + std::to_string(length) + " bytes but only " +
                               std::to_string(end - pos) + " remain");
            }
            const std::uint64_t valueEnd = pos + length;
            if (maySequence && length >= 8 && depth < kMaxDicomNesting && startsWithItem(big)) {
                items(valueEnd, inner, depth + 1);
            }
            pos = valueEnd;
        }
        if (stop != 0) {
            fail("a sequence or item has no end delimiter");
        }
    }

  private:
    bool startsWithItem(bool big) {
        const std::uint64_t at = pos;
        const std::uint32_t t = tag(pos + 4, big);
        pos = at;
        return t == kItem;
    }

    bool allZeroFrom(std::uint64_t from, std::uint64_t end) {
        in_.seekg(static_cast<std::streamoff>(from));
        char chunk[4096];
        while (from < end) {
            const auto n =
                static_cast<std::streamsize>(std::min<std::uint64_t>(end - from, sizeof chunk));
            if (!in_.read(chunk, n)) {
                return false;
            }
            for (std::streamsize b = 0; b < n; ++b) {
                if (chunk[b] != 0) {
                    return false;
                }
            }
            from += static_cast<std::uint64_t>(n);
        }
        return true;
    }

    // Sequence items until the sequence end (undefined length) or `end`.
    void items(std::uint64_t end, Syntax syntax, int depth) {
        const bool big = syntax == Syntax::ExplicitBig;
        while (pos < end) {
            const std::uint32_t t = tag(end, big);
            const std::uint32_t length = u32(end, big);
            if (t == kSequenceEnd) {
                if (length != 0) {
                    failTag(t, "(a sequence delimiter) has a non-zero length");
                }
                return;
            }
            if (t != kItem) {
                failTag(t, "found where a sequence item was expected");
            }
            if (length == kUndefined) {
                elements(end, syntax, depth, kItemEnd, false);
            } else if (length > end - pos) {
                failTag(t, "(an item) claims " + std::to_string(length) + " bytes but only " +
                               std::to_string(end - pos) + " remain");
            } else {
                const std::uint64_t itemEnd = pos + length;
                elements(itemEnd, syntax, depth, 0, false);
                pos = itemEnd;
            }
        }
        if (end == size_) {
            fail("a sequence has no end delimiter");
        }
    }

    // Encapsulated pixel data: defined-length fragments until the sequence end.
    void fragments(std::uint64_t end) {
        while (true) {
            const std::uint32_t t = tag(end, false);
            const std::uint32_t length = u32(end, false);
            if (t == kSequenceEnd) {
                if (length != 0) {
                    failTag(t, "(a sequence delimiter) has a non-zero length");
                }
                return;
            }
            if (t != kItem || length == kUndefined || length > end - pos) {
                failTag(t, "is not a complete pixel data fragment");
            }
            pos += length;
        }
    }

    const std::filesystem::path& path_;
    std::istream& in_;
    std::uint64_t size_;
};

// The data set after the meta header, inflated (raw deflate, RFC 1951), up to a size cap. A
// stream cut short inflates to a shorter data set, which the element walk then refuses.
std::string inflateDataSet(const std::filesystem::path& path, std::uint64_t from) {
    FileSource file(path);
    file.seek(from);
    GzipSource inflater(path, file, GzipSource::Format::RawDeflate);
    const std::vector<std::byte> bytes = readUpTo(inflater, kMaxInflatedBytes + 1);
    if (bytes.size() > kMaxInflatedBytes) {
        throw ScanError(path, "the deflated data set inflates past " +
                                  std::to_string(kMaxInflatedBytes >> 20) + " MiB");
    }
    return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

} // namespace

std::uint64_t checkDicomStructure(const std::filesystem::path& path) {
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    if (ec || !in) {
        throw ScanError(path, "cannot be opened");
    }
    Walker w(path, in, size);
    std::array<char, 132> head{};
    const bool hasPreamble =
        size >= 132 && in.read(head.data(), 132) && std::string(head.data() + 128, 4) == "DICM";
    if (hasPreamble) {
        w.pos = 132;
    }
    // The meta header (group 0002) is always explicit VR little endian.
    std::string syntaxUid;
    std::optional<std::uint64_t> groupLength;
    std::uint64_t groupStart = 0;
    while (w.pos + 8 <= size) {
        const std::uint64_t at = w.pos;
        const std::uint32_t t = w.tag(size, false);
        w.pos = at;
        if ((t >> 16) != 0x0002) {
            break;
        }
        w.tag(size, false);
        std::array<char, 2> vr{};
        w.read(vr.data(), 2, size);
        // GDCM asserts on any other VR in the meta header (an SQ, say).
        static constexpr const char* kMetaVrs[] = {"UL", "OB", "UI", "SH", "AE", "UR"};
        bool metaVr = false;
        for (const char* v : kMetaVrs) {
            metaVr = metaVr || (vr[0] == v[0] && vr[1] == v[1]);
        }
        if (!metaVr) {
            w.failTag(t, "(meta header) has a VR that does not belong there");
        }
        std::uint32_t length = 0;
        if (longVr(vr)) {
            (void)w.u16(size, false);
            length = w.u32(size, false);
        } else {
            length = w.u16(size, false);
        }
        if (length == kUndefined || length > size - w.pos) {
            w.failTag(t, "(meta header) claims more bytes than the file holds");
        }
        if (t == 0x00020000U) {
            std::array<unsigned char, 4> v{};
            if (length != 4) {
                w.failTag(t, "(meta group length) is not 4 bytes");
            }
            w.read(v.data(), 4, size);
            groupLength = static_cast<std::uint64_t>(v[0]) | static_cast<std::uint64_t>(v[1]) << 8 |
                          static_cast<std::uint64_t>(v[2]) << 16 |
                          static_cast<std::uint64_t>(v[3]) << 24;
            groupStart = w.pos;
        } else if (t == 0x00020010U) {
            std::string uid(length, '\0');
            w.read(uid.data(), length, size);
            while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' ')) {
                uid.pop_back();
            }
            syntaxUid = uid;
        } else {
            w.pos += length;
        }
    }
    // GDCM reads the meta header by its group length and asserts where that ends mid-element.
    if (groupLength && w.pos - groupStart != *groupLength) {
        w.fail("the meta header's group length (" + std::to_string(*groupLength) +
               ") does not match its elements (" + std::to_string(w.pos - groupStart) + ")");
    }
    // GDCM asserts reading a meta header that lacks it.
    if (hasPreamble && syntaxUid.empty()) {
        w.fail("the meta header has no Transfer Syntax UID (0002,0010)");
    }
    const auto emptyDataSet = [&path] {
        return ScanError(path, "not a well-formed DICOM file: the data set is empty");
    };
    Syntax syntax = Syntax::ExplicitLittle;
    if (syntaxUid == "1.2.840.10008.1.2.1.99") {
        // GDCM reads one more tag from the raw bytes to find the meta header's end, and asserts
        // where the file ends before it: no deflated stream is that short.
        if (size - w.pos < 8) {
            w.fail("the deflated data set is missing or cut short");
        }
        std::istringstream inflated(inflateDataSet(path, w.pos));
        const auto inflatedSize = static_cast<std::uint64_t>(inflated.str().size());
        if (inflatedSize == 0) {
            throw emptyDataSet();
        }
        Walker data(path, inflated, inflatedSize);
        data.elements(inflatedSize, Syntax::ExplicitLittle, 0, 0, false);
        return size;
    }
    if (syntaxUid == "1.2.840.10008.1.2") {
        syntax = Syntax::ImplicitLittle;
    } else if (syntaxUid == "1.2.840.10008.1.2.2") {
        syntax = Syntax::ExplicitBig;
    } else if (syntaxUid.empty() && w.pos + 6 <= size) {
        // No meta header: explicit VR if two letters follow the first tag.
        std::array<char, 6> first{};
        const std::uint64_t at = w.pos;
        w.read(first.data(), 6, size);
        w.pos = at;
        const bool letters =
            first[4] >= 'A' && first[4] <= 'Z' && first[5] >= 'A' && first[5] <= 'Z';
        syntax = letters ? Syntax::ExplicitLittle : Syntax::ImplicitLittle;
    }
    const std::uint64_t dataSetStart = w.pos;
    w.elements(size, syntax, 0, 0, true);
    const std::uint64_t end = w.paddingStart != 0 ? w.paddingStart : size;
    if (end <= dataSetStart) {
        throw emptyDataSet();
    }
    return end;
}

} // namespace steerseg::scan
