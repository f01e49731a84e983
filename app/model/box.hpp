#pragma once

// The operator's box (issue 51, docs/steering.md "The box"): the region the structure lies
// in, as the interactive challenge and ITK-SNAP's snake start from. Voxel indices of two
// opposite corners, both inside the scan and both inside the box. The surface never leaves it
// (shaders/solver/barrier_speed.glsl), classify learns the outside from its shell, and the
// first run starts from its centre (workflow_box.cpp).
#include "model/level_set_params.hpp"

#include <glm/glm.hpp>
#include <string>

namespace steerseg::model {

struct Box {
    glm::ivec3 lo{0};
    glm::ivec3 hi{0};
    bool operator==(const Box&) const = default;
};

// Throws std::invalid_argument with one line for a box that is inverted (lo > hi on an axis)
// or reaches outside the scan (dims voxels).
void validateBox(const Box& box, const glm::ivec3& dims);

// One of a box's six faces: the one at lo or at hi on an index axis (0 i, 1 j, 2 k).
struct BoxFace {
    int axis = 0;
    bool high = false;
    bool operator==(const BoxFace&) const = default;
};

[[nodiscard]] bool contains(const Box& box, const glm::ivec3& voxel);
// The box with one face moved by `voxels` along its axis, kept within the scan and never past
// the opposite face (the box keeps at least one voxel on the axis).
[[nodiscard]] Box movedFace(const Box& box, BoxFace face, int voxels, const glm::ivec3& dims);
[[nodiscard]] glm::dvec3 centreOf(const Box& box);
[[nodiscard]] glm::ivec3 sizeOf(const Box& box); // voxels along each axis
// The box grown to hold the sphere (scaled as a sphere is: sphereScale), within the scan:
// a correction that adds beyond the box moves it.
[[nodiscard]] Box boxHolding(const Box& box, const Sphere& sphere, const glm::vec3& scale,
                             const glm::ivec3& dims);
// "(i0, j0, k0)-(i1, j1, k1)", for one-line messages.
std::string describe(const Box& box);

} // namespace steerseg::model
