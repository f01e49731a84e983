#pragma once

// A structure's display colour as DICOM records it.
#include <array>
#include <cstdint>
#include <glm/glm.hpp>

namespace steerseg::exports {

// sRGB (components 0..1, clamped) -> CIELab (D65) -> DICOM's encoding of it (PS3.3 C.10.7.1.1:
// L* 0..100 and a*, b* -128..127 scaled linearly onto 0..65535): a SEG segment's Recommended
// Display CIELab Value, as dcmqi and highdicom compute it.
std::array<std::uint16_t, 3> dicomLabFromRgb(const glm::dvec3& rgb);

} // namespace steerseg::exports
