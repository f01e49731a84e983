#pragma once

#include <glm/glm.hpp>

namespace steerseg::render {

enum class CameraPreset { Anterior, Lateral, Superior };

// A perspective orbit camera in world LPS millimetres. The frame (forward, up) stays
// orthonormal; orbit rotates it about the target, zoom moves the eye along forward, pan moves
// the target in the image plane.
class Camera {
  public:
    Camera() = default;

    // Looks at a box of `extentMm` (its diagonal) around `centre` from a preset direction:
    // anterior (from the front, patient's left on the screen's right), lateral (from the
    // patient's left), superior (from above, anterior up).
    static Camera preset(CameraPreset which, const glm::dvec3& centre, double extentMm);

    void orbit(double yawDegrees, double pitchDegrees);
    void zoom(double factor); // > 1 moves closer
    void pan(double rightMm, double upMm);

    [[nodiscard]] glm::dvec3 eye() const { return target_ - forward_ * distance_; }
    [[nodiscard]] glm::dvec3 target() const { return target_; }
    [[nodiscard]] glm::dvec3 forward() const { return forward_; }
    [[nodiscard]] glm::dvec3 up() const { return up_; }
    [[nodiscard]] glm::dvec3 right() const { return glm::cross(forward_, up_); }
    [[nodiscard]] double distance() const { return distance_; }
    [[nodiscard]] double fovYDegrees() const { return fovYDegrees_; }

    // World direction of the ray through normalised device coordinates (x right, y up, in
    // [-1, 1]) for an image of the given aspect (width / height).
    [[nodiscard]] glm::dvec3 rayDirection(const glm::dvec2& ndc, double aspect) const;
    // Pixel (x right, y down, centres at +0.5) where a world point appears; z = depth along
    // forward (negative behind the eye).
    [[nodiscard]] glm::dvec3 project(const glm::dvec3& world, const glm::ivec2& size) const;

  private:
    glm::dvec3 target_{0.0};
    glm::dvec3 forward_{0.0, 1.0, 0.0};
    glm::dvec3 up_{0.0, 0.0, 1.0};
    double distance_ = 500.0;
    double fovYDegrees_ = 30.0;
};

} // namespace steerseg::render
