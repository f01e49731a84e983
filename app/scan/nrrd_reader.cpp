// NRRD (.nrrd with attached data, .nhdr with "data file:"): raw, gzip and ascii encodings,
// 2D (one slice) or 3D scalar images, world space converted to LPS.
#include "scan/affine.hpp"
#include "scan/byte_source.hpp"
#include "scan/load_checks.hpp"
#include "scan/nrrd_header.hpp"
#include "scan/readers.hpp"
#include "scan/text_header.hpp"

#include <climits>
#include <cmath>
#include <map>

namespace steerseg::scan {

namespace {

std::optional<SampleType> nrrdType(const std::string& t) {
    static const std::map<std::string, SampleType> types = {
        {"signed char", SampleType::Int8},
        {"int8", SampleType::Int8},
        {"int8_t", SampleType::Int8},
        {"uchar", SampleType::UInt8},
        {"unsigned char", SampleType::UInt8},
        {"uint8", SampleType::UInt8},
        {"uint8_t", SampleType::UInt8},
        {"short", SampleType::Int16},
        {"short int", SampleType::Int16},
        {"signed short", SampleType::Int16},
        {"signed short int", SampleType::Int16},
        {"int16", SampleType::Int16},
        {"int16_t", SampleType::Int16},
        {"ushort", SampleType::UInt16},
        {"unsigned short", SampleType::UInt16},
        {"unsigned short int", SampleType::UInt16},
        {"uint16", SampleType::UInt16},
        {"uint16_t", SampleType::UInt16},
        {"int", SampleType::Int32},
        {"signed int", SampleType::Int32},
        {"int32", SampleType::Int32},
        {"int32_t", SampleType::Int32},
        {"uint", SampleType::UInt32},
        {"unsigned int", SampleType::UInt32},
        {"uint32", SampleType::UInt32},
        {"uint32_t", SampleType::UInt32},
        {"longlong", SampleType::Int64},
        {"long long", SampleType::Int64},
        {"long long int", SampleType::Int64},
        {"signed long long", SampleType::Int64},
        {"signed long long int", SampleType::Int64},
        {"int64", SampleType::Int64},
        {"int64_t", SampleType::Int64},
        {"ulonglong", SampleType::UInt64},
        {"unsigned long long", SampleType::UInt64},
        {"unsigned long long int", SampleType::UInt64},
        {"uint64", SampleType::UInt64},
        {"uint64_t", SampleType::UInt64},
        {"float", SampleType::Float32},
        {"double", SampleType::Float64},
    };
    const auto it = types.find(t);
    return it == types.end() ? std::nullopt : std::optional(it->second);
}

// Sign flips taking the named space's axes to LPS; nullopt for spaces we cannot place.
std::optional<glm::dvec3> spaceToLps(const std::string& space) {
    if (space == "left-posterior-superior" || space == "lps") {
        return glm::dvec3(1, 1, 1);
    }
    if (space == "right-anterior-superior" || space == "ras") {
        return glm::dvec3(-1, -1, 1);
    }
    if (space == "left-anterior-superior" || space == "las") {
        return glm::dvec3(1, -1, 1);
    }
    // No patient orientation: the coordinates are taken as they stand.
    if (space == "scanner-xyz" || space == "3d-right-handed" || space == "3d-left-handed") {
        return glm::dvec3(1, 1, 1);
    }
    return std::nullopt;
}

// "(1,0,0) (0,1,0) none" -> vectors, nullopt for "none"; empty result if malformed.
std::vector<std::optional<std::vector<double>>> parseVectors(std::string_view s, bool& ok) {
    std::vector<std::optional<std::vector<double>>> out;
    ok = true;
    while (true) {
        s = trim(s);
        if (s.empty()) {
            return out;
        }
        if (s.substr(0, 4) == "none") {
            out.emplace_back(std::nullopt);
            s.remove_prefix(4);
            continue;
        }
        const std::size_t close = s.find(')');
        if (s.front() != '(' || close == std::string_view::npos) {
            ok = false;
            return out;
        }
        auto numbers = parseNumbers(s.substr(1, close - 1), true);
        if (!numbers) {
            ok = false;
            return out;
        }
        out.emplace_back(std::move(*numbers));
        s.remove_prefix(close + 1);
    }
}

} // namespace

RawDataSpec parseNrrdHeader(const std::filesystem::path& path, std::string_view text,
                            bool wholeFile, const ReadLimits& limits) {
    if (text.size() < 8 || text.substr(0, 7) != "NRRD000" || text[7] < '1' || text[7] > '9') {
        throw ScanError(path, "not a NRRD file (no NRRD000x magic)");
    }
    std::map<std::string, std::string> fields;
    std::size_t at = nextLine(text, 0)->next;
    bool ended = false;
    while (const auto line = nextLine(text, at)) {
        at = line->next;
        if (line->text.empty()) {
            ended = true;
            break;
        }
        if (line->text.front() == '#' || line->text.find(":=") != std::string_view::npos) {
            continue; // comments and key/value pairs carry nothing we use
        }
        const std::size_t colon = line->text.find(": ");
        if (colon == std::string_view::npos) {
            throw ScanError(path, "NRRD header line \"" + std::string(line->text.substr(0, 60)) +
                                      "\" is not a field");
        }
        fields[toLower(trim(line->text.substr(0, colon)))] =
            std::string(trim(line->text.substr(colon + 2)));
    }
    const auto field = [&](std::initializer_list<const char*> names) -> const std::string* {
        for (const char* n : names) {
            if (const auto it = fields.find(n); it != fields.end()) {
                return &it->second;
            }
        }
        return nullptr;
    };
    const auto require = [&](const char* name) -> const std::string& {
        const std::string* v = field({name});
        if (v == nullptr) {
            throw ScanError(path, std::string("NRRD header has no \"") + name + "\" field");
        }
        return *v;
    };

    RawDataSpec spec;
    const std::string* dataFile = field({"data file", "datafile"});
    if (dataFile != nullptr) {
        if (*dataFile == "LIST" || dataFile->find('%') != std::string::npos ||
            dataFile->rfind("LIST ", 0) == 0) {
            throw ScanError(path, "NRRD data split over several files is not supported");
        }
        spec.dataFile = *dataFile;
    } else if (!ended) {
        throw ScanError(path, wholeFile ? "NRRD header has no data (no blank line ends it and "
                                          "no \"data file\" field)"
                                        : "NRRD header does not end within the first 1 MiB");
    }
    spec.headerBytes = at;

    const auto type = nrrdType(toLower(require("type")));
    if (!type) {
        throw ScanError(path, "NRRD type \"" + require("type") + "\" is not supported");
    }
    spec.type = *type;
    const auto dimension = parseInteger(require("dimension"), 1, 16);
    if (!dimension || (*dimension != 2 && *dimension != 3)) {
        throw ScanError(path, "NRRD dimension " + require("dimension") +
                                  " is not supported (steerseg reads 2D and 3D scalar images)");
    }
    const auto ndim = static_cast<int>(*dimension);
    const auto sizes = parseNumbers(require("sizes"));
    if (!sizes || sizes->size() != static_cast<std::size_t>(ndim)) {
        throw ScanError(path, "NRRD sizes \"" + require("sizes") + "\" do not give " +
                                  std::to_string(ndim) + " axis lengths");
    }
    glm::ivec3 dims(1);
    for (int a = 0; a < ndim; ++a) {
        const double s = (*sizes)[static_cast<std::size_t>(a)];
        dims[a] = axisLength(s);
    }
    checkDims(path, dims, limits);

    const std::string encoding = toLower(require("encoding"));
    if (encoding == "raw") {
        spec.encoding = DataEncoding::Raw;
    } else if (encoding == "gzip" || encoding == "gz") {
        spec.encoding = DataEncoding::Compressed;
    } else if (encoding == "ascii" || encoding == "text" || encoding == "txt") {
        spec.encoding = DataEncoding::Ascii;
    } else {
        throw ScanError(path, "NRRD encoding \"" + encoding +
                                  "\" is not supported (raw, gzip and ascii are)");
    }
    if (const std::string* endian = field({"endian"})) {
        const std::string e = toLower(*endian);
        if (e != "little" && e != "big") {
            throw ScanError(path, "NRRD endian \"" + *endian + "\" is neither little nor big");
        }
        spec.order = e == "big" ? ByteOrder::Big : ByteOrder::Little;
    }
    if (const std::string* lines = field({"line skip", "lineskip"})) {
        const auto n = parseInteger(*lines, 0, INT_MAX);
        if (!n) {
            throw ScanError(path, "NRRD line skip \"" + *lines + "\" is not a count");
        }
        spec.lineSkip = static_cast<std::uint64_t>(*n);
    }
    if (const std::string* bytes = field({"byte skip", "byteskip"})) {
        const auto n = parseInteger(*bytes, -1, std::int64_t{1} << 50);
        if (!n || (*n == -1 && spec.encoding != DataEncoding::Raw)) {
            throw ScanError(path, "NRRD byte skip \"" + *bytes + "\" is not valid here");
        }
        // For compressed data teem skips bytes of the decompressed stream.
        if (spec.encoding == DataEncoding::Compressed) {
            spec.decodedSkip = static_cast<std::uint64_t>(*n);
        } else {
            spec.fileSkip = *n;
        }
    }

    // Geometry: space directions (columns of the index-to-world matrix) and origin.
    glm::dvec3 toLps(1.0);
    int spaceDim = 3;
    if (const std::string* space = field({"space"})) {
        const auto flips = spaceToLps(toLower(*space));
        if (!flips) {
            throw ScanError(path, "NRRD space \"" + *space + "\" is not supported");
        }
        toLps = *flips;
    } else if (const std::string* sd = field({"space dimension"})) {
        const auto n = parseInteger(*sd, 2, 3);
        if (!n) {
            throw ScanError(path, "NRRD space dimension \"" + *sd + "\" is not 2 or 3");
        }
        spaceDim = static_cast<int>(*n);
    }
    Affine affine;
    if (const std::string* dirs = field({"space directions"})) {
        bool ok = false;
        const auto vectors = parseVectors(*dirs, ok);
        if (!ok || vectors.size() != static_cast<std::size_t>(ndim)) {
            throw ScanError(path, "NRRD space directions \"" + dirs->substr(0, 80) +
                                      "\" do not give one vector per axis");
        }
        for (int a = 0; a < ndim; ++a) {
            const auto& v = vectors[static_cast<std::size_t>(a)];
            if (!v) {
                throw ScanError(path, "NRRD axis " + std::to_string(a) +
                                          " is not spatial (vector or colour data is not "
                                          "supported)");
            }
            if (v->size() != static_cast<std::size_t>(spaceDim)) {
                throw ScanError(path, "NRRD space direction " + std::to_string(a) + " has " +
                                          std::to_string(v->size()) + " components, expected " +
                                          std::to_string(spaceDim));
            }
            for (int r = 0; r < spaceDim; ++r) {
                affine.linear[a][r] = (*v)[static_cast<std::size_t>(r)];
            }
            if (spaceDim == 2) {
                affine.linear[a][2] = 0.0;
            }
        }
    } else if (const std::string* spacings = field({"spacings"})) {
        const auto s = parseNumbers(*spacings);
        if (!s || s->size() != static_cast<std::size_t>(ndim)) {
            throw ScanError(path, "NRRD spacings \"" + *spacings + "\" do not give one per axis");
        }
        for (int a = 0; a < ndim; ++a) {
            const double v = (*s)[static_cast<std::size_t>(a)];
            affine.linear[a][a] = std::isnan(v) ? 1.0 : v; // nan: unknown spacing
        }
    }
    if (ndim == 2) {
        // One slice: its normal, 1 mm thick, completes a right-handed grid.
        const glm::dvec3 normal = glm::cross(affine.linear[0], affine.linear[1]);
        const double len = glm::length(normal);
        affine.linear[2] = len > 0.0 && std::isfinite(len) ? normal / len : glm::dvec3(0, 0, 1);
    }
    if (const std::string* origin = field({"space origin"})) {
        bool ok = false;
        const auto vectors = parseVectors(*origin, ok);
        if (!ok || vectors.size() != 1 || !vectors[0] ||
            vectors[0]->size() != static_cast<std::size_t>(spaceDim)) {
            throw ScanError(path,
                            "NRRD space origin \"" + origin->substr(0, 80) + "\" is not one point");
        }
        for (int r = 0; r < spaceDim; ++r) {
            affine.offset[r] = (*vectors[0])[static_cast<std::size_t>(r)];
        }
    }
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            affine.linear[c][r] *= toLps[r];
        }
        affine.offset[r] *= toLps[r];
    }
    spec.geometry = geometryFromAffine(path, affine, dims);
    return spec;
}

Volume readNrrdFrom(const std::filesystem::path& path, SeekableSource& file,
                    const ReadLimits& limits) {
    const std::string text = readHeaderPrefix(file);
    if (text.empty()) {
        throw ScanError(path, "the file is empty");
    }
    const RawDataSpec spec = parseNrrdHeader(path, text, text.size() == file.size(), limits);
    return loadRawData(path, file, spec, limits);
}

Volume readNrrd(const std::filesystem::path& path, const ReadLimits& limits) {
    FileSource file(path);
    return readNrrdFrom(path, file, limits);
}

} // namespace steerseg::scan
