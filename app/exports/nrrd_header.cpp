#include "exports/nrrd_header.hpp"

#include "scan/affine.hpp"

#include <array>
#include <charconv>

namespace steerseg::exports {

namespace {

std::string number(double v) {
    std::array<char, 32> text{};
    const auto result = std::to_chars(text.data(), text.data() + text.size(), v);
    return std::string(text.data(), result.ptr);
}

std::string vectorText(const glm::dvec3& v) {
    return "(" + number(v.x) + "," + number(v.y) + "," + number(v.z) + ")";
}

} // namespace

std::string nrrdHeader(const Geometry& g, const std::string& comment, const std::string& keyValues,
                       int layers) {
    const scan::Affine lps = scan::affineOf(g);
    const bool layered = layers > 0;
    std::string h = "NRRD0004\n"
                    "# Complete NRRD file format specification at:\n"
                    "# http://teem.sourceforge.net/nrrd/format.html\n"
                    "# " +
                    comment +
                    "\n"
                    "type: uint8\n";
    h += layered ? "dimension: 4\n" : "dimension: 3\n";
    h += "space: left-posterior-superior\n";
    h += "sizes: " + (layered ? std::to_string(layers) + " " : std::string()) +
         std::to_string(g.dims.x) + " " + std::to_string(g.dims.y) + " " +
         std::to_string(g.dims.z) + "\n";
    h += "space directions: " + std::string(layered ? "none " : "") + vectorText(lps.linear[0]) +
         " " + vectorText(lps.linear[1]) + " " + vectorText(lps.linear[2]) + "\n";
    h += layered ? "kinds: list domain domain domain\n" : "kinds: domain domain domain\n";
    h += "endian: little\n"
         "encoding: gzip\n";
    h += "space origin: " + vectorText(lps.offset) + "\n";
    return h + keyValues + "\n";
}

} // namespace steerseg::exports
