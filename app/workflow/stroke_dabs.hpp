#pragma once

// A painted stroke's spheres: where the brush touches down along the finger's path.
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

namespace steerseg::workflow {

// The stroke's points and, between successive ones, evenly spaced centres no farther apart than
// `spacing`, so a fast drag (whose points lie far apart) leaves no gap. Points closer than
// `spacing` to the last centre kept add nothing (a finger at rest). nullopt when more than
// `maxDabs` centres would be needed. `spacing` must be positive and the points finite. Lengths
// are measured as a sphere's radius is (`scale`: model::sphereScale), so that the dabs overlap
// as much through thick slices as across them.
std::optional<std::vector<glm::dvec3>> strokeDabs(std::span<const glm::dvec3> points,
                                                  double spacing, std::size_t maxDabs,
                                                  const glm::dvec3& scale = glm::dvec3(1.0));

} // namespace steerseg::workflow
