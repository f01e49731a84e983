#include "render/render_names.hpp"

#include <array>
#include <stdexcept>
#include <utility>

namespace steerseg::render {

namespace {

template <typename E, std::size_t N>
E lookup(const std::string& word, const std::array<std::pair<const char*, E>, N>& table,
         const char* what) {
    std::string accepted;
    for (const auto& [name, value] : table) {
        if (word == name) {
            return value;
        }
        accepted += accepted.empty() ? name : std::string(", ") + name;
    }
    throw std::invalid_argument("unknown " + std::string(what) + " '" + word + "' (expected " +
                                accepted + ")");
}

} // namespace

ViewKind parseViewKind(const std::string& word) {
    return lookup(
        word,
        std::array<std::pair<const char*, ViewKind>, 4>{{{"3d", ViewKind::Volume3d},
                                                         {"axial", ViewKind::Axial},
                                                         {"coronal", ViewKind::Coronal},
                                                         {"sagittal", ViewKind::Sagittal}}},
        "view");
}

RoiMode parseRoiMode(const std::string& word) {
    return lookup(word,
                  std::array<std::pair<const char*, RoiMode>, 3>{
                      {{"inside", RoiMode::Inside}, {"dim", RoiMode::Dim}, {"off", RoiMode::Off}}},
                  "ROI mode");
}

SurfaceMode parseSurfaceMode(const std::string& word) {
    return lookup(word,
                  std::array<std::pair<const char*, SurfaceMode>, 3>{
                      {{"opaque", SurfaceMode::Opaque},
                       {"translucent", SurfaceMode::Translucent},
                       {"hidden", SurfaceMode::Hidden}}},
                  "surface mode");
}

CameraPreset parseCameraPreset(const std::string& word) {
    return lookup(
        word,
        std::array<std::pair<const char*, CameraPreset>, 3>{{{"anterior", CameraPreset::Anterior},
                                                             {"lateral", CameraPreset::Lateral},
                                                             {"superior", CameraPreset::Superior}}},
        "camera");
}

} // namespace steerseg::render
