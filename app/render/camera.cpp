#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace steerseg::render {

namespace {

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double radians) {
    // Rodrigues' formula; axis is a unit vector.
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

} // namespace

Camera Camera::preset(CameraPreset which, const glm::dvec3& centre, double extentMm) {
    Camera c;
    c.target_ = centre;
    // LPS: +x patient left, +y posterior, +z superior.
    switch (which) {
    case CameraPreset::Anterior:
        c.forward_ = {0.0, 1.0, 0.0};
        c.up_ = {0.0, 0.0, 1.0};
        break;
    case CameraPreset::Lateral:
        c.forward_ = {-1.0, 0.0, 0.0};
        c.up_ = {0.0, 0.0, 1.0};
        break;
    case CameraPreset::Superior:
        c.forward_ = {0.0, 0.0, -1.0};
        c.up_ = {0.0, -1.0, 0.0};
        break;
    }
    const double halfFov = glm::radians(c.fovYDegrees_) * 0.5;
    c.distance_ = std::max(1.0, 0.5 * extentMm) / std::sin(halfFov) * 0.8;
    return c;
}

void Camera::orbit(double yawDegrees, double pitchDegrees) {
    forward_ = glm::normalize(rotate(forward_, up_, glm::radians(yawDegrees)));
    const glm::dvec3 newRight = glm::normalize(glm::cross(forward_, up_));
    forward_ = glm::normalize(rotate(forward_, newRight, glm::radians(pitchDegrees)));
    up_ = glm::normalize(rotate(up_, newRight, glm::radians(pitchDegrees)));
}

void Camera::zoom(double factor) {
    if (factor > 0.0 && std::isfinite(factor)) {
        distance_ = std::max(1e-3, distance_ / factor);
    }
}

void Camera::pan(double rightMm, double upMm) {
    target_ += right() * rightMm + up_ * upMm;
}

glm::dvec3 Camera::rayDirection(const glm::dvec2& ndc, double aspect) const {
    const double t = std::tan(glm::radians(fovYDegrees_) * 0.5);
    return glm::normalize(forward_ + right() * (ndc.x * t * aspect) + up_ * (ndc.y * t));
}

glm::dvec3 Camera::project(const glm::dvec3& world, const glm::ivec2& size) const {
    const glm::dvec3 rel = world - eye();
    const double depth = glm::dot(rel, forward_);
    const double t = std::tan(glm::radians(fovYDegrees_) * 0.5);
    const double aspect = static_cast<double>(size.x) / static_cast<double>(size.y);
    const double ndcX = glm::dot(rel, right()) / (depth * t * aspect);
    const double ndcY = glm::dot(rel, up_) / (depth * t);
    return {(ndcX * 0.5 + 0.5) * size.x, (0.5 - ndcY * 0.5) * size.y, depth};
}

} // namespace steerseg::render
