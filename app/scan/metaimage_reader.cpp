// MetaImage (.mha / .mhd), as ITK, SimpleITK and elastix write it: single-channel 2D or 3D,
// raw or zlib-compressed, ASCII optional, either byte order.
#include "scan/affine.hpp"
#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/metaimage_header.hpp"
#include "scan/readers.hpp"
#include "scan/text_header.hpp"

#include <climits>
#include <cmath>
#include <map>

namespace steerseg::scan {

namespace {

std::optional<SampleType> metaType(const std::string& t) {
    static const std::map<std::string, SampleType> types = {
        {"met_char", SampleType::Int8},       {"met_uchar", SampleType::UInt8},
        {"met_short", SampleType::Int16},     {"met_ushort", SampleType::UInt16},
        {"met_int", SampleType::Int32},       {"met_uint", SampleType::UInt32},
        {"met_long", SampleType::Int32},      {"met_ulong", SampleType::UInt32},
        {"met_long_long", SampleType::Int64}, {"met_ulong_long", SampleType::UInt64},
        {"met_float", SampleType::Float32},   {"met_double", SampleType::Float64},
    };
    const auto it = types.find(t);
    return it == types.end() ? std::nullopt : std::optional(it->second);
}

bool isTrue(const std::string& v) {
    const std::string l = toLower(v);
    return l == "true" || l == "1" || l == "yes";
}

} // namespace

RawDataSpec parseMetaImageHeader(const std::filesystem::path& path, std::string_view text,
                                 const ReadLimits& limits) {
    // MetaIO matches keys exactly; matching them case-insensitively costs nothing.
    std::map<std::string, std::string> fields;
    std::size_t at = 0;
    bool ended = false;
    while (const auto line = nextLine(text, at)) {
        at = line->next;
        const std::string_view l = trim(line->text);
        if (l.empty()) {
            continue;
        }
        const std::size_t eq = l.find('=');
        if (eq == std::string_view::npos) {
            throw ScanError(path, fields.empty()
                                      ? "not a MetaImage header (no \"Key = Value\" "
                                        "lines)"
                                      : "MetaImage header line \"" + std::string(l.substr(0, 60)) +
                                            "\" is not a field");
        }
        const std::string key = toLower(trim(l.substr(0, eq)));
        fields[key] = std::string(trim(l.substr(eq + 1)));
        if (key == "elementdatafile") {
            ended = true; // MetaIO: always the last field; the data follows
            break;
        }
    }
    if (!ended) {
        throw ScanError(path, text.size() >= kMaxTextHeaderBytes
                                  ? "MetaImage header does not end within the first 1 MiB"
                                  : "MetaImage header has no ElementDataFile field");
    }
    const auto field = [&](std::initializer_list<const char*> names) -> const std::string* {
        for (const char* n : names) {
            if (const auto it = fields.find(n); it != fields.end()) {
                return &it->second;
            }
        }
        return nullptr;
    };
    const auto require = [&](const char* key, const char* name) -> const std::string& {
        const std::string* v = field({key});
        if (v == nullptr) {
            throw ScanError(path, std::string("MetaImage header has no ") + name + " field");
        }
        return *v;
    };

    RawDataSpec spec;
    spec.headerBytes = at;
    if (const std::string* object = field({"objecttype"}); object && toLower(*object) != "image") {
        throw ScanError(path, "MetaImage ObjectType " + *object + " is not an image");
    }
    const auto ndims = parseInteger(require("ndims", "NDims"), 1, 16);
    if (!ndims || (*ndims != 2 && *ndims != 3)) {
        throw ScanError(path, "MetaImage NDims " + require("ndims", "NDims") +
                                  " is not supported (steerseg reads 2D and 3D images)");
    }
    const auto n = static_cast<std::size_t>(*ndims);
    const auto type = metaType(toLower(require("elementtype", "ElementType")));
    if (!type) {
        throw ScanError(path, "MetaImage ElementType " + require("elementtype", "ElementType") +
                                  " is not supported");
    }
    spec.type = *type;
    if (const std::string* channels = field({"elementnumberofchannels"})) {
        if (parseInteger(*channels, 1, 1) != 1) {
            throw ScanError(path, "MetaImage has " + *channels +
                                      " channels per voxel; steerseg reads single-channel images");
        }
    }
    const auto sizes = parseNumbers(require("dimsize", "DimSize"));
    if (!sizes || sizes->size() != n) {
        throw ScanError(path, "MetaImage DimSize \"" + require("dimsize", "DimSize") +
                                  "\" does not give " + std::to_string(n) + " axis lengths");
    }
    glm::ivec3 dims(1);
    for (std::size_t a = 0; a < n; ++a) {
        const double s = (*sizes)[a];
        dims[static_cast<int>(a)] = axisLength(s);
    }
    checkDims(path, dims, limits);

    const auto vectorField = [&](std::initializer_list<const char*> names, std::size_t count,
                                 const char* what) -> std::optional<std::vector<double>> {
        const std::string* v = field(names);
        if (v == nullptr) {
            return std::nullopt;
        }
        auto numbers = parseNumbers(*v);
        if (!numbers || numbers->size() != count) {
            throw ScanError(path, std::string("MetaImage ") + what + " \"" + v->substr(0, 80) +
                                      "\" does not hold " + std::to_string(count) + " numbers");
        }
        return numbers;
    };
    glm::dvec3 spacing(1.0);
    if (const auto s = vectorField({"elementspacing", "elementsize"}, n, "ElementSpacing")) {
        for (std::size_t a = 0; a < n; ++a) {
            spacing[static_cast<int>(a)] = (*s)[a];
        }
    }
    Affine affine;
    if (const auto o = vectorField({"offset", "origin", "position"}, n, "Offset")) {
        for (std::size_t a = 0; a < n; ++a) {
            affine.offset[static_cast<int>(a)] = (*o)[a];
        }
    }
    glm::dmat3 direction(1.0);
    // ITK reads TransformMatrix as the axis directions one after another: the first n numbers
    // are the direction of i (column 0 of the direction matrix).
    if (const auto t =
            vectorField({"transformmatrix", "rotation", "orientation"}, n * n, "TransformMatrix")) {
        for (std::size_t c = 0; c < n; ++c) {
            for (std::size_t r = 0; r < n; ++r) {
                direction[static_cast<int>(c)][static_cast<int>(r)] = (*t)[c * n + r];
            }
        }
    }
    for (int c = 0; c < 3; ++c) {
        affine.linear[c] = direction[c] * spacing[c];
    }
    spec.geometry = geometryFromAffine(path, affine, dims);

    const std::string* msb = field({"binarydatabyteordermsb", "elementbyteordermsb"});
    spec.order = msb != nullptr && isTrue(*msb) ? ByteOrder::Big : ByteOrder::Little;
    const std::string* binary = field({"binarydata"});
    const std::string* compressed = field({"compresseddata"});
    if (compressed != nullptr && isTrue(*compressed)) {
        spec.encoding = DataEncoding::Compressed;
    } else if (binary != nullptr && !isTrue(*binary)) {
        spec.encoding = DataEncoding::Ascii;
    }
    const std::string& dataFile = require("elementdatafile", "ElementDataFile");
    if (toLower(dataFile) != "local") {
        if (dataFile.rfind("LIST", 0) == 0 || dataFile.find('%') != std::string::npos) {
            throw ScanError(path, "MetaImage data split over several files is not supported");
        }
        spec.dataFile = dataFile;
        if (const std::string* skip = field({"headersize"})) {
            const auto bytes = parseInteger(*skip, -1, std::int64_t{1} << 50);
            if (!bytes || (*bytes == -1 && spec.encoding != DataEncoding::Raw)) {
                throw ScanError(path, "MetaImage HeaderSize \"" + *skip + "\" is not valid here");
            }
            spec.fileSkip = *bytes;
        }
    }
    return spec;
}

Volume readMetaImageFrom(const std::filesystem::path& path, SeekableSource& file,
                         const ReadLimits& limits) {
    const std::string text = readHeaderPrefix(file);
    if (text.empty()) {
        throw ScanError(path, "the file is empty");
    }
    return loadRawData(path, file, parseMetaImageHeader(path, text, limits), limits);
}

Volume readMetaImage(const std::filesystem::path& path, const ReadLimits& limits) {
    FileSource file(path);
    return readMetaImageFrom(path, file, limits);
}

} // namespace steerseg::scan
