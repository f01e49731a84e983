#pragma once

// The structures of a session (issue 49, docs/structures.md): what each one is called and means,
// as the operator and the DICOM SEG name it. Plain values: the workflow keeps the list, the
// config names the site's kinds, the exports code them.
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::model {

// A coded concept (code value, coding scheme designator, code meaning), as DICOM's segmented
// property category and type are coded: ("49755003", "SCT", "Morphologically Abnormal
// Structure").
struct StructureCode {
    std::string value;
    std::string scheme;
    std::string meaning;
    bool operator==(const StructureCode&) const = default;
};

// SNOMED CT "Tissue" (85756007): what a structure means when nothing more is known (free text).
StructureCode tissueCode();

// One structure: its name (unique in the session, at most kMaxStructureName characters, no line
// break, no '|'), what it is, its colour (r g b within 0..1) and whether the views show it.
struct StructureInfo {
    std::string name;
    StructureCode category = tissueCode();
    StructureCode type = tissueCode();
    glm::dvec3 colour{0.945, 0.839, 0.569};
    bool visible = true;
    bool operator==(const StructureInfo&) const = default;
};
inline constexpr std::size_t kMaxStructureName = 64; // a DICOM SEG's Segment Label (LO)
inline constexpr std::size_t kMaxStructures = 64;

// Why `name` cannot name a structure ("" when it can).
std::string structureNameProblem(std::string_view name);
// Why `code` is not a code (an empty value, scheme or meaning, or a line break in one); "" when
// it is.
std::string structureCodeProblem(const StructureCode& code);

// What a new structure called `name` is: the site's kind of that name (the config's
// [[structures]], compared without case) or free text coded as tissue, in the palette's
// colour for the `index`th structure when the kind gives none.
StructureInfo structureFor(std::string_view name, const std::vector<StructureInfo>& kinds,
                           std::size_t index);
// The palette new structures take their colours from, in order (3D Slicer's first labels').
glm::dvec3 paletteColour(std::size_t index);

// The name the first structure of a session has until the operator renames it.
inline constexpr std::string_view kFirstStructureName = "Segment 1";

} // namespace steerseg::model
