#include "model/structure.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace steerseg::model {

namespace {

bool sameWithoutCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

bool hasLineBreak(std::string_view s) {
    return s.find_first_of("\r\n") != std::string_view::npos;
}

} // namespace

StructureCode tissueCode() {
    return {"85756007", "SCT", "Tissue"};
}

std::string structureNameProblem(std::string_view name) {
    if (name.empty()) {
        return "a structure needs a name";
    }
    if (name.size() > kMaxStructureName) {
        return "the structure name '" + std::string(name.substr(0, 20)) + "...' is longer than " +
               std::to_string(kMaxStructureName) + " characters";
    }
    if (hasLineBreak(name) || name.find('|') != std::string_view::npos) {
        return "a structure name may not hold a line break or '|'";
    }
    if (std::isspace(static_cast<unsigned char>(name.front())) != 0 ||
        std::isspace(static_cast<unsigned char>(name.back())) != 0) {
        return "the structure name '" + std::string(name) + "' starts or ends with a space";
    }
    return {};
}

std::string structureCodeProblem(const StructureCode& code) {
    if (code.value.empty() || code.scheme.empty() || code.meaning.empty()) {
        return "a code needs a value, a scheme and a meaning";
    }
    if (hasLineBreak(code.value) || hasLineBreak(code.scheme) || hasLineBreak(code.meaning)) {
        return "a code may not hold a line break";
    }
    return {};
}

glm::dvec3 paletteColour(std::size_t index) {
    // 3D Slicer's GenericAnatomyColors for its first labels: the colours an operator who moves
    // between the two tools already reads.
    static constexpr std::array<std::array<double, 3>, 8> kPalette{{{0.945, 0.839, 0.569},
                                                                    {0.694, 0.478, 0.396},
                                                                    {0.435, 0.722, 0.824},
                                                                    {0.847, 0.396, 0.310},
                                                                    {0.867, 0.510, 0.396},
                                                                    {0.565, 0.933, 0.565},
                                                                    {0.753, 0.408, 0.345},
                                                                    {0.863, 0.961, 0.078}}};
    const auto& c = kPalette[index % kPalette.size()];
    return {c[0], c[1], c[2]};
}

StructureInfo structureFor(std::string_view name, const std::vector<StructureInfo>& kinds,
                           std::size_t index) {
    for (const StructureInfo& kind : kinds) {
        if (sameWithoutCase(kind.name, name)) {
            StructureInfo out = kind;
            out.name = std::string(name);
            out.visible = true;
            return out;
        }
    }
    StructureInfo out;
    out.name = std::string(name);
    out.colour = paletteColour(index);
    return out;
}

} // namespace steerseg::model
