#include "render/slice_frame.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace steerseg::render {

namespace {

struct ScreenAxes {
    glm::dvec3 right;
    glm::dvec3 up;
};

ScreenAxes screenAxes(ViewKind kind) {
    switch (kind) {
    case ViewKind::Axial:
        return {{1.0, 0.0, 0.0}, {0.0, -1.0, 0.0}};
    case ViewKind::Coronal:
        return {{1.0, 0.0, 0.0}, {0.0, 0.0, 1.0}};
    case ViewKind::Sagittal:
        return {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
    case ViewKind::Volume3d:
        break;
    }
    throw std::invalid_argument("not a slice view");
}

int closestAxis(const glm::dmat3& direction, const glm::dvec3& world, int skipA, int skipB) {
    int best = -1;
    double bestDot = -1.0;
    for (int a = 0; a < 3; ++a) {
        if (a == skipA || a == skipB) {
            continue;
        }
        const double d = std::abs(glm::dot(direction[a], world));
        if (d > bestDot) {
            bestDot = d;
            best = a;
        }
    }
    return best;
}

} // namespace

char patientSide(const glm::dvec3& w) {
    const glm::dvec3 a = glm::abs(w);
    if (a.x >= a.y && a.x >= a.z) {
        return w.x >= 0.0 ? 'L' : 'R';
    }
    if (a.y >= a.z) {
        return w.y >= 0.0 ? 'P' : 'A';
    }
    return w.z >= 0.0 ? 'S' : 'I';
}

int sliceAxisFor(const Geometry& geometry, ViewKind kind) {
    const ScreenAxes s = screenAxes(kind);
    return closestAxis(geometry.direction, glm::cross(s.right, s.up), -1, -1);
}

SliceFrame sliceFrame(const Geometry& g, const ViewParams& params) {
    if (params.size.x <= 0 || params.size.y <= 0) {
        throw std::invalid_argument("image size must be positive");
    }
    if (!(params.zoom > 0.0) || !std::isfinite(params.zoom)) {
        throw std::invalid_argument("zoom must be a positive number");
    }
    const ScreenAxes s = screenAxes(params.kind);
    SliceFrame f;
    f.sliceAxis = closestAxis(g.direction, glm::cross(s.right, s.up), -1, -1);
    f.axisU = closestAxis(g.direction, s.right, f.sliceAxis, -1);
    f.axisV = 3 - f.sliceAxis - f.axisU;
    const int depth = g.dims[f.sliceAxis];
    f.slice = params.slice < 0 ? depth / 2 : params.slice;
    if (f.slice >= depth) {
        throw std::invalid_argument("slice " + std::to_string(f.slice) + " is outside 0.." +
                                    std::to_string(depth - 1));
    }
    const double signU = glm::dot(g.direction[f.axisU], s.right) >= 0.0 ? 1.0 : -1.0;
    const double signV = glm::dot(g.direction[f.axisV], s.up) >= 0.0 ? 1.0 : -1.0;
    const double extentU = g.dims[f.axisU] * g.spacing[f.axisU];
    const double extentV = g.dims[f.axisV] * g.spacing[f.axisV];
    f.pixelMm = std::max(extentU / params.size.x, extentV / params.size.y) / params.zoom;

    glm::dvec3 centre = 0.5 * (glm::dvec3(g.dims) - 1.0);
    centre[f.sliceAxis] = f.slice;
    centre[f.axisU] += signU * params.pan.x / g.spacing[f.axisU];
    centre[f.axisV] += signV * params.pan.y / g.spacing[f.axisV];
    f.stepRight = glm::dvec3(0.0);
    f.stepRight[f.axisU] = signU * f.pixelMm / g.spacing[f.axisU];
    f.stepDown = glm::dvec3(0.0);
    f.stepDown[f.axisV] = -signV * f.pixelMm / g.spacing[f.axisV];
    f.origin = centre - f.stepRight * (0.5 * params.size.x - 0.5) -
               f.stepDown * (0.5 * params.size.y - 0.5);

    // Name each edge by where its world direction actually points.
    const glm::dvec3 rightWorld = g.direction * (g.spacing * f.stepRight);
    const glm::dvec3 upWorld = -(g.direction * (g.spacing * f.stepDown));
    f.labels = {patientSide(-rightWorld), patientSide(rightWorld), patientSide(upWorld),
                patientSide(-upWorld)};
    return f;
}

} // namespace steerseg::render
