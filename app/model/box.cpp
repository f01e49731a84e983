#include "model/box.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace steerseg::model {

void validateBox(const Box& box, const glm::ivec3& dims) {
    static constexpr const char* kAxes = "ijk";
    for (int a = 0; a < 3; ++a) {
        if (box.lo[a] > box.hi[a]) {
            std::ostringstream msg;
            msg << "the box " << describe(box) << " is inverted on " << kAxes[a] << ": give "
                << kAxes[a] << "0 <= " << kAxes[a] << "1";
            throw std::invalid_argument(msg.str());
        }
        if (box.lo[a] < 0 || box.hi[a] > dims[a] - 1) {
            std::ostringstream msg;
            msg << "the box " << describe(box) << " reaches outside the scan (" << dims.x << " x "
                << dims.y << " x " << dims.z << " voxels: indices 0.." << dims[a] - 1 << " on "
                << kAxes[a] << ")";
            throw std::invalid_argument(msg.str());
        }
    }
}

bool contains(const Box& box, const glm::ivec3& voxel) {
    return glm::all(glm::greaterThanEqual(voxel, box.lo)) &&
           glm::all(glm::lessThanEqual(voxel, box.hi));
}

Box movedFace(const Box& box, BoxFace face, int voxels, const glm::ivec3& dims) {
    Box out = box;
    if (face.axis < 0 || face.axis > 2) {
        return out;
    }
    const int a = face.axis;
    // In 64 bits: a flood of detents must not wrap around.
    if (face.high) {
        const long long to = static_cast<long long>(box.hi[a]) + voxels;
        out.hi[a] = static_cast<int>(std::clamp<long long>(to, box.lo[a], dims[a] - 1));
    } else {
        const long long to = static_cast<long long>(box.lo[a]) + voxels;
        out.lo[a] = static_cast<int>(std::clamp<long long>(to, 0, box.hi[a]));
    }
    return out;
}

glm::dvec3 centreOf(const Box& box) {
    return 0.5 * (glm::dvec3(box.lo) + glm::dvec3(box.hi));
}

glm::ivec3 sizeOf(const Box& box) {
    return box.hi - box.lo + 1;
}

Box boxHolding(const Box& box, const Sphere& sphere, const glm::vec3& scale,
               const glm::ivec3& dims) {
    Box out = box;
    for (int a = 0; a < 3; ++a) {
        // The sphere's reach along the axis, in that axis's voxels (sphereNorm).
        const float reach = sphere.radius / std::max(scale[a], 1e-6F);
        const int lo = static_cast<int>(std::floor(sphere.centre[a] - reach));
        const int hi = static_cast<int>(std::ceil(sphere.centre[a] + reach));
        out.lo[a] = std::clamp(std::min(out.lo[a], lo), 0, dims[a] - 1);
        out.hi[a] = std::clamp(std::max(out.hi[a], hi), 0, dims[a] - 1);
    }
    return out;
}

std::string describe(const Box& box) {
    std::ostringstream s;
    s << "(" << box.lo.x << ", " << box.lo.y << ", " << box.lo.z << ")-(" << box.hi.x << ", "
      << box.hi.y << ", " << box.hi.z << ")";
    return s.str();
}

} // namespace steerseg::model
