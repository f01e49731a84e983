#pragma once

#include "render/camera.hpp"
#include "render/render_params.hpp"

#include <string>

namespace steerseg::render {

// Words used on the command line and in settings. Each parser throws std::invalid_argument
// naming the accepted words.
ViewKind parseViewKind(const std::string& word);         // 3d axial coronal sagittal
RoiMode parseRoiMode(const std::string& word);           // inside dim off
SurfaceMode parseSurfaceMode(const std::string& word);   // opaque translucent hidden
CameraPreset parseCameraPreset(const std::string& word); // anterior lateral superior

} // namespace steerseg::render
